"""Binary glTF 2.0 (``.glb``): a triangle mesh of walls and floors for engines that import meshes.

Written with numpy and ``struct`` alone. The scene has one root node, ``building``, whose
rotation turns the plan's z-up frame into glTF's y-up one (vertex positions are plan
coordinates in metres); under it a node ``walls`` (every wall box, each closed on its own),
``lintels`` and ``doors`` (closed entrances) when there are any, a node per room floor named
after the room (``room <id>: <function> (<label>)``, with its id, labels and area in
``extras``), and an empty node ``robot_start`` at the simulator's start pose.
"""

from __future__ import annotations

import json
import math
import struct
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from realistic_indoor.io.world3d.mesh import Z_UP_TO_Y_UP, Mesh, boxes_mesh, floor_mesh
from realistic_indoor.io.world3d.scene import (
    WorldOptions,
    building_boxes,
    comment_lines,
    room_notes,
    start_pose,
    write_world,
)

if TYPE_CHECKING:
    from realistic_indoor.building import Building

__all__ = ["glb_bytes", "write"]

_FLOAT, _UINT = 5126, 5125
_ARRAY_BUFFER, _ELEMENT_ARRAY_BUFFER = 34962, 34963
_MATERIALS = {
    "wall": (0.85, 0.85, 0.82, 1.0),
    "floor": (0.7, 0.7, 0.7, 1.0),
    "door": (0.55, 0.38, 0.22, 1.0),
}
_BOX_GROUPS = (("walls", "wall", "wall"), ("lintels", "lintel", "wall"), ("doors", "door", "door"))
"""Node name, box kind and material of each group of boxes."""


def write(
    building: Building, path: str | Path, *, options: WorldOptions | None = None, **fields: Any
) -> list[Path]:
    """Write ``building`` as binary glTF (``.glb``).

    ``options`` (or its fields as keywords) and errors are those of
    :func:`~realistic_indoor.io.world3d.scene.write_world`.
    """
    return write_world(building, path, lambda b, o, _path: glb_bytes(b, o), options, fields)


class _Builder:
    """Collects meshes into one binary buffer and the glTF JSON that describes it.

    Materials are numbered in the order meshes first use them, so none is left unused.
    """

    def __init__(self) -> None:
        self.buffer = bytearray()
        self.doc: dict[str, Any] = {"accessors": [], "bufferViews": [], "meshes": [], "nodes": []}
        self.materials: list[str] = []

    def _view(self, data: bytes, target: int) -> int:
        self.buffer += bytes(-len(self.buffer) % 4)
        self.doc["bufferViews"].append(
            {"buffer": 0, "byteOffset": len(self.buffer), "byteLength": len(data), "target": target}
        )
        self.buffer += data
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, view: int, count: int, kind: str, component: int, extra: dict) -> int:
        self.doc["accessors"].append(
            {"bufferView": view, "componentType": component, "count": count, "type": kind, **extra}
        )
        return len(self.doc["accessors"]) - 1

    def mesh(self, name: str, mesh: Mesh, material: str) -> int:
        """Add ``mesh`` (positions as float32, indices as uint32); returns the mesh index."""
        positions = np.ascontiguousarray(mesh.vertices, dtype="<f4")
        indices = np.ascontiguousarray(mesh.faces, dtype="<u4").ravel()
        bounds = {"min": positions.min(axis=0).tolist(), "max": positions.max(axis=0).tolist()}
        pos = self._accessor(
            self._view(positions.tobytes(), _ARRAY_BUFFER), len(positions), "VEC3", _FLOAT, bounds
        )
        idx = self._accessor(
            self._view(indices.tobytes(), _ELEMENT_ARRAY_BUFFER), len(indices), "SCALAR", _UINT, {}
        )
        if material not in self.materials:
            self.materials.append(material)
        primitive = {
            "attributes": {"POSITION": pos},
            "indices": idx,
            "material": self.materials.index(material),
        }
        self.doc["meshes"].append({"name": name, "primitives": [primitive]})
        return len(self.doc["meshes"]) - 1

    def node(self, node: dict[str, Any]) -> int:
        self.doc["nodes"].append(node)
        return len(self.doc["nodes"]) - 1


def glb_bytes(building: Building, options: WorldOptions) -> bytes:
    """The ``.glb`` file's bytes: a 12-byte header, the JSON chunk, the binary chunk."""
    from realistic_indoor.version import __version__

    b = _Builder()
    root = b.node({"name": "building", "rotation": list(Z_UP_TO_Y_UP), "children": []})
    boxes = building_boxes(building, options)
    for node_name, kind, material in _BOX_GROUPS:
        group = [box for box in boxes if box.kind == kind]
        if group:
            mesh = b.mesh(node_name, boxes_mesh(group), material)
            b.doc["nodes"][root]["children"].append(b.node({"name": node_name, "mesh": mesh}))
    for note in room_notes(building):
        r = note.room
        mesh = b.mesh(f"floor {r.id}", floor_mesh(r), "floor")
        extras = {"room_id": r.id, "function": r.function, "label": r.label.value, "area_m2": r.area}
        node = {"name": f"room {r.id}: {r.function} ({r.label.value})", "mesh": mesh, "extras": extras}
        b.doc["nodes"][root]["children"].append(b.node(node))
    _start_node(b, root, building)
    doc = {
        "asset": {
            "version": "2.0",
            "generator": f"realistic-indoor {__version__}",
            "extras": {"notes": comment_lines(building, options, "glTF 2.0 mesh")},
        },
        "scene": 0,
        "scenes": [{"name": str(building.metadata.get("name") or "building"), "nodes": [root]}],
        **b.doc,
        "materials": [_material(name, _MATERIALS[name]) for name in b.materials],
        "buffers": [{"byteLength": len(b.buffer)}],
    }
    return _glb(json.dumps(doc, separators=(",", ":"), ensure_ascii=False).encode("utf-8"), bytes(b.buffer))


def _material(name: str, rgba: tuple[float, ...]) -> dict[str, Any]:
    pbr = {"baseColorFactor": list(rgba), "metallicFactor": 0.0, "roughnessFactor": 0.9}
    return {"name": name, "pbrMetallicRoughness": pbr, "doubleSided": name == "floor"}


def _start_node(b: _Builder, root: int, building: Building) -> None:
    pose = start_pose(building)
    if pose is None:
        return
    x, y, yaw = pose
    turn = [0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)]
    b.doc["nodes"][root]["children"].append(
        b.node({"name": "robot_start", "translation": [x, y, 0.0], "rotation": turn})
    )


def _glb(json_chunk: bytes, bin_chunk: bytes) -> bytes:
    """Pack the two chunks, each padded to 4 bytes (JSON with spaces, binary with zeros)."""
    json_chunk += b" " * (-len(json_chunk) % 4)
    bin_chunk += bytes(-len(bin_chunk) % 4)
    total = 12 + 8 + len(json_chunk) + 8 + len(bin_chunk)
    return b"".join(
        [
            struct.pack("<4sII", b"glTF", 2, total),
            struct.pack("<I4s", len(json_chunk), b"JSON"),
            json_chunk,
            struct.pack("<I4s", len(bin_chunk), b"BIN\x00"),
            bin_chunk,
        ]
    )
