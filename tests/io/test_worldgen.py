import math
import warnings
import xml.etree.ElementTree as ET

import pytest

from realistic_indoor.building import Building, Door, Room, SemanticLabel
from realistic_indoor.errors import ConfigError, PlanFormatError
from realistic_indoor.io import load, save
from realistic_indoor.io.worldgen import DOOR_WIDTH_M, LossyExportWarning, read, write


@pytest.fixture
def grid_office():
    """An office drawn on the 3 m grid: a corridor along the bottom, four rooms above, two entrances."""
    rooms = (
        Room.rectangle("c", "corridor", "corridor", (0, 0, 30, 3)),
        Room.rectangle("a", "medium", "office", (0, 3, 6, 9)),
        Room.rectangle("b", "big", "lab", (6, 3, 15, 12)),
        Room.rectangle("s", "small", "toilet", (15, 3, 18, 6)),
        Room.rectangle("h", "hall", "lobby", (18, 3, 30, 12)),
    )
    doors = (
        Door("d1", "a", "c", 4.5, 3, 0.9, 0),
        Door("d2", "b", "c", 7.5, 3, 0.9, 0),
        Door("d3", "s", "c", 16.5, 3, 0.9, 0),
        Door("d4", "h", "c", 25.5, 3, 0.9, 0),
        Door("d5", "a", "b", 6, 7.5, 0.9, math.pi / 2),
        Door("e1", "c", None, 0, 1.5, 1.2, math.pi / 2),
        Door("e2", "h", None, 25.5, 12, 1.0, 0),
    )
    return Building("office", rooms, doors)


def _by_box(b):
    return {tuple(round(v, 9) for v in r.bounds): r for r in b.rooms}


def _door_keys(b):
    box = {r.id: tuple(round(v, 9) for v in r.bounds) for r in b.rooms}
    return {
        (
            frozenset(box[rid] for rid in d.rooms),
            d.is_exterior,
            round(d.x, 9),
            round(d.y, 9),
            round(math.sin(d.angle_rad), 9),
        )
        for d in b.doors
    }


def test_worldgen__grid_building_round_trips(grid_office, tmp_path):
    path = tmp_path / "office.wg.xml"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert save(grid_office, path) == [path]
    back = load(path)
    assert {k: r.label for k, r in _by_box(back).items()} == {
        k: r.label for k, r in _by_box(grid_office).items()
    }
    assert _door_keys(back) == _door_keys(grid_office)
    assert {d.width_m for d in back.doors} == {DOOR_WIDTH_M}
    assert not back.validate()


def test_worldgen__writes_modules_and_doors_on_the_grid(grid_office, tmp_path):
    path = tmp_path / "office.wg.xml"
    write(grid_office, path)
    root = ET.parse(path).getroot()
    assert (root.tag, root.get("depth"), root.get("width"), root.get("name")) == (
        "world",
        "4",
        "10",
        "office",
    )
    modules = {(r.get("name"), r.get("x"), r.get("y"), r.get("theta")) for r in root.findall("room")}
    assert ("corridor_1x10.t3d", "3", "0", "0") in modules  # bottom row of a 4-row world
    assert ("big_3x3.t3d", "0", "2", "0") in modules
    doors = {(d.get("x"), d.get("y"), d.get("direction")) for d in root.findall("door")}
    assert ("3", "1", "0") in doors  # office a -> corridor: top edge of corridor cell (3, 1)
    assert ("1", "2", "1") in doors  # office a -> lab b: left edge of cell (1, 2)
    assert ("3", "0", "1") in doors  # west entrance of the corridor, on the world's edge


NIST_WORLD = """<?xml version="1.0" encoding="UTF-8"?>
<world depth="8" width="8" name="nist">
  <room name="hallway.t3d" x="0" y="0" theta="0" />
  <room name="hallway.t3d" x="0" y="1" theta="0" />
  <room name="hallway.t3d" x="0" y="2" theta="0" />
  <room name="hallway.t3d" x="1" y="2" theta="0" />
  <room name="hallway.t3d" x="2" y="2" theta="0" />
  <room name="OfficeLit.t3d" x="1" y="0" theta="0" />
  <room name="SpaceOffice.t3d" x="1" y="3" theta="1" />
  <room name="Cubicle.t3d" x="2" y="3" theta="0" />
  <door x="1" y="0" direction="0" />
  <door x="1" y="3" direction="3" />
  <door x="2" y="3" direction="1" />
  <door x="0" y="0" direction="2" />
</world>
"""


def test_worldgen__reads_the_tools_own_worlds(tmp_path):
    path = tmp_path / "nist.xml"  # a .xml file whose root is <world> is World Generator XML
    path.write_text(NIST_WORLD)
    b = load(path)
    rooms = {r.id: r for r in b.rooms}
    assert rooms["hallway-0-0"].bounds == (0, 21, 9, 24)  # the top row's three hallway cells
    assert rooms["hallway-1-2"].bounds == (6, 15, 9, 21)
    assert rooms["room-1-3"].bounds == (9, 18, 15, 21)  # a 2x1 module turned a quarter: 1 row, 2 columns
    assert (rooms["room-1-0"].label, rooms["room-1-0"].function) == (SemanticLabel.SMALL, "office")
    assert (rooms["room-1-3"].label, rooms["room-2-3"].label) == (SemanticLabel.MEDIUM, SemanticLabel.BIG)
    opening = b.doors[0]
    assert set(opening.rooms) == {"hallway-0-0", "hallway-1-2"} and opening.width_m == 3.0
    door = {d.id: d for d in b.doors}
    assert set(door["door-1-0-0"].rooms) == {"hallway-0-0", "room-1-0"}
    assert (door["door-1-3-1"].x, door["door-1-3-1"].y) == (9.0, 19.5)
    assert door["door-0-0-0"].rooms == ("hallway-0-0",)  # on the world's north edge: an entrance
    assert b.metadata["name"] == "nist"
    assert not b.validate()


def test_worldgen__custom_modules_from_mapping_or_rooms_xml(tmp_path):
    path = tmp_path / "w.wg.xml"
    path.write_text(
        '<world depth="2" width="3" name="w"><room name="Mine.t3d" x="0" y="0" theta="0"/></world>'
    )
    assert read(path, modules={"Mine.t3d": (2, 3)}).rooms[0].bounds == (0, 0, 9, 6)
    db = tmp_path / "rooms.xml"
    db.write_text('<roomList><room name="Mine" src="Mine.t3d" size="1, 2, 1" tag="x"/></roomList>')
    assert read(path, modules=db).rooms[0].bounds == (0, 3, 6, 6)


def test_worldgen__off_grid_building_warns_what_it_lost(tmp_path):
    rooms = (
        Room.rectangle("c", "corridor", "corridor", (0, 0, 20, 2)),
        Room.rectangle("a", "medium", "office", (0, 2, 4.2, 6)),
        Room.rectangle("k", "small", "closet", (4.2, 2, 5.0, 3)),
    )
    b = Building("office", rooms, (Door("d1", "a", "c", 2, 2), Door("d2", "k", "c", 4.6, 2)))
    with pytest.warns(LossyExportWarning, match=r"3 m grid.*rooms changed area"):
        write(b, tmp_path / "b.wg.xml")
    back = load(tmp_path / "b.wg.xml")
    assert not [f for f in back.validate(require_entrance=False) if f.code in ("overlap", "door_off_wall")]
    with pytest.raises(ConfigError, match="does not fit"):
        write(b, tmp_path / "strict.wg.xml", strict=True)


def test_worldgen__real_plan_exports_to_a_valid_world(real_plans_dir, tmp_path):
    b = load(real_plans_dir / "office/ED21.xml")
    with pytest.warns(LossyExportWarning):
        save(b, tmp_path / "ed21.wg.xml")
    back = load(tmp_path / "ed21.wg.xml")
    assert 0.8 * len(b.rooms) <= len(back.rooms) <= len(b.rooms)
    assert not [f for f in back.validate(require_entrance=False) if f.code in ("overlap", "door_off_wall")]


@pytest.mark.parametrize(
    ("body", "match"),
    [
        ('<room name="Nope.t3d" x="0" y="0" theta="0"/>', r'room name="Nope\.t3d".*unknown module.*modules='),
        ('<room name="Cubicle.t3d" x="0" y="0" theta="0"/>', "leaves the 3x3 world"),
        (
            '<room name="small_1x1.t3d" x="0" y="0" theta="0"/><room name="big_2x2.t3d" x="0" y="0" theta="0"/>',
            "overlaps",
        ),
        (
            '<room name="small_1x1.t3d" x="0" y="0" theta="0"/><door x="2" y="2" direction="0"/>',
            "no room on either side",
        ),
        ('<room name="small_1x1.t3d" x="one" y="0" theta="0"/>', "x must be an integer, not 'one'"),
    ],
)
def test_worldgen__bad_worlds_are_one_line_errors(tmp_path, body, match):
    path = tmp_path / "bad.wg.xml"
    path.write_text(f'<world depth="3" width="3" name="bad">{body}</world>')
    with pytest.raises(PlanFormatError, match=match) as e:
        read(path)
    assert "\n" not in str(e.value) and "bad.wg.xml" in str(e.value)


def test_worldgen__not_a_world(tmp_path):
    path = tmp_path / "plan.wg.xml"
    path.write_text("<building/>")
    with pytest.raises(PlanFormatError, match="not <world>"):
        read(path)
    with pytest.raises(PlanFormatError, match="no such file"):
        read(tmp_path / "missing.wg.xml")


def test_worldgen__empty_building_cannot_be_written(tmp_path):
    with pytest.raises(ConfigError, match="without rooms"):
        write(Building("office", ()), tmp_path / "e.wg.xml")
