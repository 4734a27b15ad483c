"""The boxes every 3D export shares, the options, file names and whole-or-nothing writes."""

from __future__ import annotations

import errno
import math

import numpy as np
import pytest

import realistic_indoor as ri
from realistic_indoor import files
from realistic_indoor.building import Building, Room
from realistic_indoor.errors import ConfigError, PlanFormatError, RealisticIndoorError
from realistic_indoor.io import format_of, load, save
from realistic_indoor.io.world3d import WorldOptions, building_boxes

ENDINGS = ("sdf", "world", "mjcf.xml", "glb", "obj")


def test_boxes__walls_are_the_plan_segments_with_square_caps(slanted, box_segments):
    boxes = [b for b in building_boxes(slanted, WorldOptions()) if b.kind == "wall"]
    walls = np.asarray(slanted.walls)
    assert [b.name for b in boxes] == [f"wall_{i}" for i in range(len(walls))]
    found = box_segments(
        np.array([b.centre for b in boxes]),
        np.array([b.size[0] for b in boxes]),
        np.array([b.yaw_rad for b in boxes]),
        0.1,
    )
    assert np.abs(found - walls).max() < 1e-9
    assert all(b.size[1:] == (0.1, 2.5) and b.centre[2] == 1.25 for b in boxes)


def test_boxes__slanted_wall_gives_a_box_along_each_piece(slanted):
    slant = math.atan2(4, 2)
    along = [
        b
        for b in building_boxes(slanted, WorldOptions())
        if b.kind == "wall" and math.isclose(b.yaw_rad % math.pi, slant)
    ]
    assert len(along) == 2  # the slanted wall, cut in two by its door
    assert sum(b.size[0] - 0.1 for b in along) == pytest.approx(math.hypot(2, 4) - 0.9)


def test_boxes__lintels_over_every_door_and_closed_entrances(slanted):
    boxes = building_boxes(slanted, WorldOptions(door_height_m=2.0, exterior_doors_open=False))
    lintels = {b.name: b for b in boxes if b.kind == "lintel"}
    doors = {b.name: b for b in boxes if b.kind == "door"}
    assert set(lintels) == {"lintel_d1", "lintel_e1"}
    assert set(doors) == {"door_e1"}
    assert lintels["lintel_e1"].size == pytest.approx((1.2, 0.1, 0.5))
    assert lintels["lintel_e1"].centre == pytest.approx((0.0, 2.0, 2.25))
    assert doors["door_e1"].size == pytest.approx((1.2, 0.1, 2.0))
    no_lintels = building_boxes(slanted, WorldOptions(door_height_m=2.5))
    assert {b.kind for b in no_lintels} == {"wall"}


@pytest.mark.parametrize(
    ("fields", "message"),
    [
        ({"wall_height_m": 0.0}, r"wall_height_m must be a finite number in \[0.1, 10\] m, got 0.0"),
        ({"wall_height_m": -2.5}, r"wall_height_m must be a finite number in \[0.1, 10\] m"),
        ({"wall_height_m": math.nan}, r"wall_height_m must be a finite number in \[0.1, 10\] m"),
        ({"wall_thickness_m": 0}, r"wall_thickness_m must be a finite number in \[0.01, 1\] m"),
        ({"door_height_m": 3.0}, "door_height_m must be at most wall_height_m"),
        ({"exterior_doors_open": "no"}, "exterior_doors_open must be True or False"),
    ],
)
def test_options__bad_values_are_config_errors(fields, message):
    with pytest.raises(ConfigError, match=message):
        WorldOptions(**fields)


@pytest.mark.parametrize("ending", ENDINGS)
def test_save__non_positive_wall_height_is_config_error_and_writes_nothing(tiny_office, tmp_path, ending):
    with pytest.raises(ConfigError, match=r"wall_height_m must be a finite number in \[0.1, 10\] m, got -1"):
        save(tiny_office, tmp_path / f"plan.{ending}", wall_height_m=-1)
    assert list(tmp_path.iterdir()) == []


def test_save__options_as_object_or_keywords_not_both(tiny_office, tmp_path):
    a, b = tmp_path / "a" / "plan.sdf", tmp_path / "b" / "plan.sdf"
    save(tiny_office, a, options=WorldOptions(wall_height_m=3.0))
    save(tiny_office, b, wall_height_m=3.0)
    assert a.read_text(encoding="utf-8") == b.read_text(encoding="utf-8")
    assert "<size>10.1 0.1 3</size>" in a.read_text(encoding="utf-8")
    with pytest.raises(ConfigError, match="not both"):
        save(tiny_office, a, options=WorldOptions(), wall_height_m=3.0)
    with pytest.raises(ConfigError, match="unknown 3D world option 'height'; known: wall_height_m"):
        save(tiny_office, a, height=3.0)


def test_format_of__mjcf_wins_over_floor_plan_xml_by_the_longer_ending():
    assert format_of("office.mjcf.xml") == "mjcf"
    assert format_of("OFFICE.MJCF.XML") == "mjcf"
    assert format_of("office.xml") == "floorplan"
    assert [format_of(f"a.{e}") for e in ("sdf", "world", "glb", "obj")] == ["sdf", "sdf", "glb", "obj"]


def test_format_of__unknown_ending_lists_the_known_ones_with_the_3d_worlds():
    with pytest.raises(RealisticIndoorError, match="cannot tell the format") as e:
        format_of("office.dae")
    for ending in (".json", ".xml", ".yaml", ".sdf", ".world", ".mjcf.xml", ".glb", ".obj"):
        assert ending in str(e.value)


@pytest.mark.parametrize("ending", ENDINGS)
def test_load__3d_worlds_are_written_not_read(tiny_office, tmp_path, ending):
    path = tmp_path / f"plan.{ending}"
    save(tiny_office, path)
    with pytest.raises(PlanFormatError, match="can be written but not read"):
        load(path)


@pytest.mark.parametrize("ending", ENDINGS)
def test_save__same_building_same_bytes(tiny_office, tmp_path, ending):
    a, b = tmp_path / "a" / f"plan.{ending}", tmp_path / "b" / f"plan.{ending}"
    save(tiny_office, a)
    save(tiny_office, b)
    assert a.read_bytes() == b.read_bytes()


@pytest.mark.parametrize("ending", ENDINGS)
def test_save__failed_write_keeps_the_previous_file(tiny_office, tmp_path, monkeypatch, ending):
    target = tmp_path / f"plan.{ending}"
    save(tiny_office, target, wall_height_m=3.0)
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}

    def disk_full(*_args):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(files.os, "fsync", disk_full)  # the data is written, then the disk is full
    with pytest.raises(OSError, match="No space left"):
        save(tiny_office, target)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before


@pytest.mark.parametrize("ending", ENDINGS)
def test_save__every_room_is_named_in_the_file(tiny_office, tmp_path, ending):
    path = tmp_path / f"plan.{ending}"
    save(tiny_office, path)
    data = path.read_bytes().decode("utf-8", "replace")
    for room in tiny_office.rooms:
        assert f"room {room.id}: {room.function} ({room.label.value})" in data or (
            f"room_{room.id}_{room.function}_{room.label.value}" in data
        )


def test_save__start_pose_is_the_simulators(office, tmp_path):
    from realistic_indoor.sim import World

    x, y, yaw = World(office).start_pose
    save(office, tmp_path / "o.sdf")
    save(office, tmp_path / "o.mjcf.xml")
    sdf = tmp_path.joinpath("o.sdf").read_text(encoding="utf-8")
    mjcf = tmp_path.joinpath("o.mjcf.xml").read_text(encoding="utf-8")
    from realistic_indoor.io.world3d.scene import fmt

    assert (
        f'<frame name="robot_start">\n      <pose>{fmt(x)} {fmt(y)} 0 0 0 {fmt(math.remainder(yaw, 2 * math.pi))}</pose>'
        in sdf
    )
    assert f'<site name="robot_start" pos="{fmt(x)} {fmt(y)} 0"' in mjcf


def test_save__metadata_and_frame_are_comments(office, tmp_path):
    save(office, tmp_path / "o.sdf")
    text = tmp_path.joinpath("o.sdf").read_text(encoding="utf-8")
    assert f"<!-- metadata seed: {office.metadata['seed']} -->" in text
    assert "frame: metres, the plan's x and y (as the ROS map export), z up" in text
    assert "--" not in text.replace("<!--", "").replace("-->", "")


@pytest.mark.parametrize("kind", ["office", "school", "house", "random"])
def test_save__every_generated_type_exports(kind, tmp_path):
    b = ri.generate(kind, seed=5)
    for ending in ENDINGS:
        (path,) = save(b, tmp_path / f"{kind}.{ending}")
        assert path.stat().st_size > 1000


@pytest.mark.parametrize("ending", ENDINGS)
def test_save__no_start_pose_where_the_robot_fits_nowhere(tmp_path, ending):
    closet = Building("house", (Room.rectangle("c", "small", "closet", (0, 0, 0.6, 0.6)),), (), {})
    (path,) = save(closet, tmp_path / f"closet.{ending}")
    data = path.read_bytes()
    assert b"robot_start" not in data
    if ending in ("sdf", "world", "mjcf.xml"):
        assert b"no robot start: no free floor is clear enough of walls" in data
