"""Wavefront OBJ (``.obj``): the ``.glb`` export's mesh as text, for tools that read only OBJ.

OBJ has no units, no transforms and no agreed up axis; the file is written y-up, as most
importers (Blender, Unity, Unreal) read OBJ: a plan point ``(x, y)`` at height ``z`` is the
vertex ``x z -y`` (metres), the same positions a glTF reader gets from the ``.glb``. One object
(``o``) per group: ``walls``, ``lintels``, ``doors``, then one per room floor named
``room_<id>_<function>_<label>``; the building's notes and each room's label are ``#`` comments.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from realistic_indoor.io.world3d.mesh import Mesh, boxes_mesh, floor_mesh, y_up
from realistic_indoor.io.world3d.scene import (
    WorldOptions,
    building_boxes,
    comment_lines,
    fmt,
    room_notes,
    safe_name,
    write_world,
)

if TYPE_CHECKING:
    from realistic_indoor.building import Building

__all__ = ["obj_text", "write"]


def write(
    building: Building, path: str | Path, *, options: WorldOptions | None = None, **fields: Any
) -> list[Path]:
    """Write ``building`` as a Wavefront OBJ mesh (``.obj``).

    ``options`` (or its fields as keywords) and errors are those of
    :func:`~realistic_indoor.io.world3d.scene.write_world`.
    """
    return write_world(building, path, lambda b, o, _path: obj_text(b, o), options, fields)


def obj_text(building: Building, options: WorldOptions) -> str:
    """The OBJ file's text."""
    lines = [f"# {line}" for line in comment_lines(building, options, "Wavefront OBJ mesh (y up)")]
    boxes = building_boxes(building, options)
    groups: list[tuple[str, Mesh]] = [
        (name, boxes_mesh([b for b in boxes if b.kind == kind]))
        for name, kind in (("walls", "wall"), ("lintels", "lintel"), ("doors", "door"))
    ]
    for note in room_notes(building):
        r = note.room
        lines.append(f"# {note.text}")
        groups.append((safe_name(f"room_{r.id}_{r.function}_{r.label.value}"), floor_mesh(r)))
    first = 1
    for name, mesh in groups:
        if not len(mesh.faces):
            continue
        lines.append(f"o {name}")
        lines += [f"v {fmt(x)} {fmt(y)} {fmt(z)}" for x, y, z in y_up(mesh.vertices)]
        lines += [f"f {a + first} {b + first} {c + first}" for a, b, c in mesh.faces.tolist()]
        first += len(mesh.vertices)
    return "\n".join(lines) + "\n"
