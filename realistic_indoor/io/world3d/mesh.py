"""Triangle meshes of the 3D exports: closed boxes and room floors, in the plan's frame (z up)."""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

import numpy as np

if TYPE_CHECKING:
    from realistic_indoor.building import Room
    from realistic_indoor.io.world3d.scene import Box

__all__ = ["Z_UP_TO_Y_UP", "Mesh", "boxes_mesh", "floor_mesh", "y_up"]

_BOX_FACES = np.array(
    [
        (0, 2, 1), (0, 3, 2),  # bottom, facing down
        (4, 5, 6), (4, 6, 7),  # top, facing up
        (0, 1, 5), (0, 5, 4),
        (1, 2, 6), (1, 6, 5),
        (2, 3, 7), (2, 7, 6),
        (3, 0, 4), (3, 4, 7),
    ],
    dtype=np.uint32,
)  # fmt: skip
"""Triangles of a box whose corners are :meth:`Box.corners`, counter-clockwise seen from outside."""

Z_UP_TO_Y_UP = (-(0.5**0.5), 0.0, 0.0, 0.5**0.5)
"""Quaternion ``(x, y, z, w)`` turning the plan's z-up frame into glTF's y-up one: -90 deg about x."""


class Mesh(NamedTuple):
    """An indexed triangle mesh.

    Attributes:
        vertices: ``(V, 3)`` float64 positions (m).
        faces: ``(F, 3)`` uint32 vertex indices, counter-clockwise seen from the front (outside).
    """

    vertices: np.ndarray
    faces: np.ndarray


def boxes_mesh(boxes: list[Box]) -> Mesh:
    """All ``boxes`` as one mesh: 8 vertices and 12 triangles each, every box closed on its own."""
    if not boxes:
        return Mesh(np.zeros((0, 3)), np.zeros((0, 3), dtype=np.uint32))
    vertices = np.concatenate([b.corners() for b in boxes])
    offsets = (np.arange(len(boxes), dtype=np.uint32) * 8)[:, None, None]
    faces = (_BOX_FACES[None] + offsets).reshape(-1, 3)
    return Mesh(vertices, faces)


def floor_mesh(room: Room) -> Mesh:
    """The room's floor at ``z = 0``: its outline cut into triangles facing up (constrained Delaunay)."""
    import shapely

    triangles = shapely.constrained_delaunay_triangles(room.polygon)
    corners = np.array([np.asarray(t.exterior.coords)[:3] for t in triangles.geoms]).reshape(-1, 3, 2)
    (ux, uy), (vx, vy) = (corners[:, 1] - corners[:, 0]).T, (corners[:, 2] - corners[:, 0]).T
    twice_area = ux * vy - uy * vx
    corners = corners[np.abs(twice_area) > 0]
    flip = twice_area[np.abs(twice_area) > 0] < 0
    corners[flip] = corners[flip][:, ::-1]
    points, faces = np.unique(corners.reshape(-1, 2), axis=0, return_inverse=True)
    vertices = np.column_stack([points, np.zeros(len(points))])
    return Mesh(vertices, faces.reshape(-1, 3).astype(np.uint32))


def y_up(vertices: np.ndarray) -> np.ndarray:
    """Plan coordinates ``(x, y, z)`` (z up) as y-up coordinates ``(x, z, -y)``, the same turn as :data:`Z_UP_TO_Y_UP`."""
    return np.column_stack([vertices[:, 0], vertices[:, 2], -vertices[:, 1]])
