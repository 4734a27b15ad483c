"""Meshes (``.glb``, ``.obj``): valid binary glTF, re-read by trimesh, closed boxes, the floor area.

The trimesh tests need the ``sim3d`` extra and skip with that reason without it; the glTF
container checks run everywhere.
"""

from __future__ import annotations

import json
import math
import struct

import numpy as np
import pytest

from realistic_indoor.io import save
from realistic_indoor.io.world3d import WorldOptions, building_boxes


def _glb(path):
    """The JSON and binary chunks of a ``.glb``, after checking its header and chunk layout."""
    data = path.read_bytes()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert (magic, version, length) == (b"glTF", 2, len(data))
    json_length, json_type = struct.unpack_from("<I4s", data, 12)
    bin_length, bin_type = struct.unpack_from("<I4s", data, 20 + json_length)
    assert (json_type, bin_type) == (b"JSON", b"BIN\x00")
    assert json_length % 4 == 0 and bin_length % 4 == 0
    assert 28 + json_length + bin_length == len(data)
    doc = json.loads(data[20 : 20 + json_length])
    return doc, data[28 + json_length :]


def test_glb__container_accessors_and_names(tiny_office, tmp_path):
    save(tiny_office, tmp_path / "t.glb")
    doc, binary = _glb(tmp_path / "t.glb")
    assert doc["asset"]["version"] == "2.0"
    assert doc["buffers"] == [{"byteLength": len(binary)}]
    for accessor in doc["accessors"]:
        view = doc["bufferViews"][accessor["bufferView"]]
        assert view["byteOffset"] % 4 == 0 and view["byteOffset"] + view["byteLength"] <= len(binary)
        if accessor["type"] == "VEC3":
            points = np.frombuffer(binary, "<f4", accessor["count"] * 3, view["byteOffset"]).reshape(-1, 3)
            assert (
                points.min(axis=0).tolist() == accessor["min"]
                and points.max(axis=0).tolist() == accessor["max"]
            )
    root = doc["nodes"][doc["scenes"][0]["nodes"][0]]
    assert root["name"] == "building" and root["rotation"] == pytest.approx(
        [-math.sqrt(0.5), 0, 0, math.sqrt(0.5)]
    )
    names = [doc["nodes"][i]["name"] for i in root["children"]]
    assert names == [
        "walls",
        "lintels",
        "room c: corridor (corridor)",
        "room a: office (medium)",
        "room b: office (medium)",
        "robot_start",
    ]
    a = doc["nodes"][root["children"][3]]
    assert a["extras"] == {"room_id": "a", "function": "office", "label": "medium", "area_m2": 20.0}


@pytest.fixture(scope="module")
def load_mesh():
    """``load_mesh(path)``: the file as trimesh reads it, ``({name: geometry}, scene)``.

    One geometry per OBJ object, vertices kept as written (not merged).
    """
    trimesh = pytest.importorskip(
        "trimesh", reason="trimesh is in the sim3d extra: pip install -e '.[sim3d]'"
    )

    def load(path):
        scene = trimesh.load_scene(path, process=False, split_objects=True)
        return dict(scene.geometry), scene

    return load


@pytest.mark.parametrize("ending", ["glb", "obj"])
@pytest.mark.parametrize("plan", ["office", "slanted", "tiny_office"])
def test_mesh__each_wall_box_closed_and_floor_area_is_the_buildings(
    plan, ending, request, tmp_path, load_mesh
):
    b = request.getfixturevalue(plan)
    save(b, tmp_path / f"m.{ending}", exterior_doors_open=False)
    geometry, scene = load_mesh(tmp_path / f"m.{ending}")
    boxes = building_boxes(b, WorldOptions(exterior_doors_open=False))
    for group, kind in (("walls", "wall"), ("lintels", "lintel"), ("doors", "door")):
        expected = [x for x in boxes if x.kind == kind]
        parts = geometry[group].split(only_watertight=False)
        assert len(parts) == len(expected)
        assert all(p.is_watertight and p.is_winding_consistent for p in parts)
        assert sum(p.volume for p in parts) == pytest.approx(
            sum(math.prod(x.size) for x in expected), rel=1e-4
        )
    floors = [g for name, g in geometry.items() if name.startswith(("floor", "room"))]
    assert len(floors) == len(b.rooms)
    assert sum(f.area for f in floors) == pytest.approx(b.area, rel=1e-5)
    assert scene.bounds[:, 1] == pytest.approx([0.0, 2.5], abs=1e-5)  # y up: floor at 0, walls to 2.5 m


def test_glb__room_labels_are_node_names(office, tmp_path, load_mesh):
    save(office, tmp_path / "o.glb")
    _geometry, scene = load_mesh(tmp_path / "o.glb")
    for room in office.rooms:
        assert f"room {room.id}: {room.function} ({room.label.value})" in scene.graph.nodes
    assert "robot_start" in scene.graph.nodes


def test_glb__plan_frame_under_the_y_up_turn(tiny_office, tmp_path, load_mesh):
    """A plan point (x, y) at height z is (x, z, -y) in glTF's y-up world, as in the .obj."""
    save(tiny_office, tmp_path / "t.glb")
    save(tiny_office, tmp_path / "t.obj")
    _geometry, glb = load_mesh(tmp_path / "t.glb")
    _geometry, obj = load_mesh(tmp_path / "t.obj")
    expected = [[-0.05, 0.0, -6.05], [10.05, 2.5, 0.05]]  # x 0..10, y 0..6, walls' caps 0.05 m beyond
    assert glb.bounds == pytest.approx(np.array(expected), abs=1e-5)
    assert obj.bounds == pytest.approx(np.array(expected), abs=1e-5)


@pytest.mark.slow
def test_mesh__every_shared_real_plan(real_plans_dir, tmp_path, load_mesh):
    from realistic_indoor.io import load

    for plan in sorted(real_plans_dir.glob("*/*.xml")):
        b = load(plan)
        save(b, tmp_path / "real.glb")
        geometry, _scene = load_mesh(tmp_path / "real.glb")
        parts = geometry["walls"].split(only_watertight=False)
        assert len(parts) == len(b.walls) and all(p.is_watertight for p in parts), plan.name
        floors = sum(g.area for name, g in geometry.items() if name.startswith("floor"))
        assert floors == pytest.approx(b.area, rel=1e-5), plan.name
        save(b, tmp_path / "real.obj")
        geometry, _scene = load_mesh(tmp_path / "real.obj")
        assert len(geometry["walls"].split(only_watertight=False)) == len(b.walls), plan.name
