"""The shared real floor plans (../shared/data/real_floorplans): every one loads, and the reader
keeps what the files hold."""

import statistics
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from realistic_indoor.building import BuildingType
from realistic_indoor.cli import main
from realistic_indoor.io import load

# The plans' overlapping outlines are repaired with a warning each (tests/io/test_plan_repairs.py).
pytestmark = pytest.mark.filterwarnings("ignore::realistic_indoor.io.floorplan.PlanRepairWarning")

REAL_PLANS = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "real_floorplans"
ALL_PLANS = sorted(p.relative_to(REAL_PLANS).as_posix() for p in REAL_PLANS.glob("*/*.xml"))

COUNTED = [
    "office/ED21.xml",
    "office/AtlanticSuites.xml",
    "office/floor-1024x523.xml",
    "school/Borchen4_updated.xml",
    "school/FALAELEM1_updated.xml",
    "school/putnamjuniorhigh_updated.xml",  # one portal without a segment: still a door
]
RELIABLY_SCALED = [
    "office/floorplanMAIN.xml",
    "office/floorplanLOWER.xml",
    "office/executive-office-floor-plans-l-a622d60bb7a76a60.xml",
    "school/Franch1_updated.xml",
    "school/Lamuniere1_updated.xml",
    "school/Sicurezza_1_updated.xml",
]


def _counts_in_file(path: Path) -> tuple[int, int]:
    """Rooms and distinct portal segments, counted straight from the XML."""
    root = ET.parse(path).getroot()
    spaces = root.findall("floor/spaces/space")
    portals = {p.findtext("linesegment") for s in spaces for p in s.findall("portals/portal")}
    return len(spaces), len(portals)


@pytest.mark.parametrize("name", ALL_PLANS)
def test_real_plans__every_plan_loads(real_plans_dir, name):
    b = load(real_plans_dir / name)
    assert b.building_type is BuildingType(name.split("/")[0])
    assert b.rooms and b.doors
    assert all(r.polygon.is_valid and r.area > 0 for r in b.rooms)
    assert all(rid in b.room_by_id for d in b.doors for rid in d.rooms)
    x0, y0, _, _ = b.bounds
    assert (x0, y0) == pytest.approx((0, 0))
    assert b.metadata["source"] == str(real_plans_dir / name)
    assert b.metadata["scale_m_per_px"] > 0
    assert not [f for f in b.validate(wall_tolerance_m=0.3) if f.code in ("door_off_wall", "unknown_room")]


def test_real_plans__all_55_present(real_plans_dir):
    assert len(ALL_PLANS) == 55


@pytest.mark.parametrize("name", COUNTED)
def test_real_plans__rooms_and_doors_match_the_file(real_plans_dir, name):
    path = real_plans_dir / name
    rooms, portals = _counts_in_file(path)
    b = load(path)
    assert (len(b.rooms), len(b.doors)) == (rooms, portals)
    assert b.entrances == ()


@pytest.mark.parametrize("name", RELIABLY_SCALED)
def test_real_plans__areas_are_square_metres(real_plans_dir, name):
    b = load(real_plans_dir / name)
    ordinary = [r.area for r in b.rooms if r.function in ("office", "classroom")]
    assert ordinary and all(5 <= a <= 200 for a in ordinary)
    medium = [r.area for r in b.rooms if r.label.value == "medium"]
    assert 10 <= statistics.median(medium) <= 100
    assert 200 <= b.area <= 20_000


def test_real_plans__repairs_are_reported(real_plans_dir):
    b = load(real_plans_dir / "school/Vieilley1_updated.xml")
    rooms, portals = _counts_in_file(real_plans_dir / "school/Vieilley1_updated.xml")
    assert (len(b.rooms), len(b.doors)) == (rooms - 1, portals)
    dropped = [r for r in b.metadata["repairs"] if r["action"].startswith("dropped the space")]
    assert [r["element"] for r in dropped] == ['space id="d4025b4c-2183-40a1-aeb6-54acb4d21162"']


@pytest.mark.parametrize("name", ALL_PLANS)
def test_real_plans__every_plan_gets_an_entrance_when_asked(real_plans_dir, name):
    from realistic_indoor.io.floorplan_xml import read

    b = read(real_plans_dir / name, infer_entrances=True)
    assert b.entrances
    assert {d.id for d in b.entrances} == {e["door"] for e in b.metadata["inferred_entrances"]["doors"]}
    found = b.validate(wall_tolerance_m=0.3)
    assert not [f for f in found if f.code in ("door_off_wall", "no_entrance")]


def test_real_plans__inferred_entrances_are_on_entrance_outer_walls(real_plans_dir):
    from realistic_indoor.io.floorplan_xml import read

    b = read(real_plans_dir / "office/floorplanMAIN.xml", infer_entrances=True)
    assert b.entrances
    assert {b.room(d.room_a).function for d in b.entrances} == {"entrance"}
    assert b.metadata["inferred_entrances"]["rule"] == "entrance spaces"
    found = b.validate(wall_tolerance_m=0.3)
    assert not [f for f in found if f.code in ("door_off_wall", "no_entrance")]


@pytest.mark.filterwarnings("ignore:the building does not fit")  # World Generator's grid loses area
@pytest.mark.parametrize("ending", [".json", ".xml", ".wg.xml"])
def test_cli__info_and_convert_a_real_plan(real_plans_dir, tmp_path, capsys, ending):
    plan = str(real_plans_dir / "school/Borchen4_updated.xml")
    assert main(["info", plan]) == 0
    assert "rooms: 10" in capsys.readouterr().out
    out = tmp_path / f"plan{ending}"
    assert main(["convert", plan, "-o", str(out)]) == 0
    assert load(out).rooms


def test_cli__bad_plan_is_one_line_error(tmp_path, capsys):
    bad = tmp_path / "bad.xml"
    bad.write_text("<building><floor>")
    assert main(["info", str(bad)]) == 1
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "bad.xml" in err and "malformed XML" in err
