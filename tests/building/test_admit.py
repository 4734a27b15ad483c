"""The gate for buildings from outside: what it refuses, what it repairs, and what it leaves alone."""

import json
import math
import warnings
from pathlib import Path

import gymnasium as gym
import pytest

import realistic_indoor  # noqa: F401 - registers the environments
from realistic_indoor.building import Building, Door, Room, admit_building
from realistic_indoor.errors import PlanFormatError, PlanRepairWarning
from realistic_indoor.generator import generate
from realistic_indoor.io import load
from realistic_indoor.io.json_format import dumps

pytestmark = pytest.mark.filterwarnings("ignore::realistic_indoor.errors.PlanRepairWarning")


def _two_rooms(outline_a=((0, 0), (4, 0), (4, 3), (0, 3)), door_rooms=("a", "b"), **door) -> Building:
    a = Room("a", "small", "office", outline_a)
    b = Room.rectangle("b", "corridor", "corridor", (4, 0, 6, 3))
    spec = {"x": 4.0, "y": 1.5, "width_m": 0.9, "angle_rad": math.pi / 2, **door}
    return Building("office", (a, b), (Door("d", *door_rooms, **spec), Door("e", "b", None, 6.0, 1.5)))


def _refusal(building: Building, source: str = "plan.json") -> str:
    with pytest.raises(PlanFormatError) as e:
        admit_building(building, source)
    message = str(e.value)
    assert "\n" not in message and message.startswith(f"{source}: ")
    return message


def test_a_valid_building_passes_as_the_same_object():
    b = _two_rooms()
    assert admit_building(b) is b


@pytest.mark.parametrize("kind", ["office", "school", "house", "random"])
def test_generated_buildings_pass_unchanged(kind):
    for seed in range(3):
        b = generate(kind, seed=seed)
        assert admit_building(b) is b


def test_every_shared_real_plan_passes_unchanged(real_plans_dir: Path):
    from realistic_indoor.io.floorplan import read

    plans = sorted(real_plans_dir.glob("*/*.xml"))
    assert len(plans) == 55
    for path in plans:
        b = read(path)
        assert admit_building(b, path) is b, path


def test_no_rooms_is_refused():
    assert "no rooms" in _refusal(Building("office", ()))


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, 1e300, -2e7])
def test_a_vertex_that_is_not_finite_or_out_of_extent_is_refused(bad):
    message = _refusal(_two_rooms(outline_a=((0, 0), (4, 0), (4, bad), (0, 3))))
    assert "room 'a'" in message and "finite coordinate" in message


def test_a_footprint_beyond_the_largest_span_is_refused():
    far = Room.rectangle("far", "big", "office", (2500, 0, 2510, 10))
    b = _two_rooms()
    message = _refusal(Building("office", (*b.rooms, far), b.doors))
    assert "2510 m x 10 m" in message and "metres" in message


def test_a_door_naming_a_missing_room_is_refused():
    message = _refusal(_two_rooms(door_rooms=("a", "ghost")))
    assert "door 'd'" in message and "'ghost'" in message


@pytest.mark.parametrize(("field", "value"), [("width_m", 0.0), ("width_m", math.nan), ("x", math.inf)])
def test_a_door_with_a_bad_number_is_refused(field, value):
    assert "door 'd'" in _refusal(_two_rooms(**{field: value}))


def test_repeated_and_non_string_ids_are_refused():
    b = _two_rooms()
    twice = Building("office", (b.rooms[0], Room.rectangle("a", "small", "office", (4, 0, 6, 3))), ())
    assert "2 rooms have this id" in _refusal(twice)
    numbered = Building("office", (Room.rectangle(7, "small", "office", (0, 0, 3, 3)),), ())
    assert "non-empty string" in _refusal(numbered)


def test_an_outline_with_two_vertices_is_refused():
    assert "2 vertices" in _refusal(_two_rooms(outline_a=((0, 0), (4, 0))))


def test_a_bow_tie_is_refused_not_repaired():
    # Two triangles of 6 m2 each: keeping one would drop half the area.
    message = _refusal(_two_rooms(outline_a=((0, 0), (4, 3), (4, 0), (0, 3))))
    assert "room 'a'" in message and "50.0%" in message


# A 10 m square whose last edge runs from (0, 10) to (0.3, -0.3), crossing the bottom edge at
# x = 0.3 * 10 / 10.3: a small loop below y = 0 (a triangle) and the main part, a quadrilateral.
_CROSSING_X = 0.3 * 10 / 10.3
_LOOPED = ((0, 0), (10, 0), (10, 10), (0, 10), (0.3, -0.3))
_MAIN_AREA = 100 - 0.5 * _CROSSING_X * 10
_LOOP_AREA = 0.5 * _CROSSING_X * 0.3


def test_a_small_self_crossing_loop_is_cut_off_with_a_warning():
    b = Building(
        "office", (Room("a", "big", "office", _LOOPED),), (Door("e", "a", None, 10, 5, 0.9, math.pi / 2),)
    )
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        fixed = admit_building(b, "plan.json")
    assert fixed.rooms[0].area == pytest.approx(_MAIN_AREA)
    assert fixed.rooms[0].polygon.is_valid
    repairs = [str(w.message) for w in caught if issubclass(w.category, PlanRepairWarning)]
    share = _LOOP_AREA / (_MAIN_AREA + _LOOP_AREA)
    assert len(repairs) == 1 and repairs[0].startswith("plan.json: room 'a': invalid outline")
    assert f"{share:.2%}" in repairs[0]
    assert fixed.metadata["repairs"][0]["defect"] == "invalid_outline"
    assert fixed.doors == b.doors and b.rooms[0].outline == _LOOPED  # the input is not changed
    with pytest.raises(PlanFormatError, match="without strict"):
        admit_building(b, "plan.json", strict=True)


def _write(path: Path, building_text: str) -> Path:
    path.write_text(building_text, encoding="utf-8")
    return path


def test_load_sends_every_format_through_the_gate(tmp_path):
    data = json.loads(dumps(_two_rooms()))
    data["rooms"][0]["outline"][2] = [4, float("nan")]
    with pytest.raises(PlanFormatError, match="room 'a'"):
        load(_write(tmp_path / "nan.json", json.dumps(data)))
    data["rooms"] = []
    data["doors"] = []
    with pytest.raises(PlanFormatError, match="has no rooms"):
        load(_write(tmp_path / "empty.json", json.dumps(data)))


def test_a_json_plan_that_is_not_utf8_is_one_plan_format_error(tmp_path):
    path = tmp_path / "latin1.json"
    path.write_bytes(dumps(_two_rooms()).replace('"office"', '"b\u00fcro"').encode("latin-1"))
    with pytest.raises(PlanFormatError, match="not UTF-8 text"):
        load(path)


def test_a_huge_world_generator_grid_is_refused_before_allocating(tmp_path):
    path = _write(tmp_path / "huge.wg.xml", '<world name="w" depth="100000" width="100000"></world>')
    with pytest.raises(PlanFormatError, match="300000 m x 300000 m"):
        load(path)


def test_environments_refuse_a_bad_building_in_one_line(tmp_path):
    bad = _two_rooms(door_rooms=("a", "ghost"))
    with pytest.raises(PlanFormatError, match=r"EnvConfig\.building: door 'd'"):
        gym.make("OfficeExplore-v0", building=bad)
    env = gym.make("OfficeExplore-v0")
    with pytest.raises(PlanFormatError, match=r"reset\(options\['building'\]\): door 'd'"):
        env.reset(seed=0, options={"building": bad})
    path = tmp_path / "plan.json"
    path.write_text(dumps(bad), encoding="utf-8")
    with pytest.raises(PlanFormatError, match="door 'd'"):
        gym.make("OfficeExplore-v0", plan_path=str(path))
