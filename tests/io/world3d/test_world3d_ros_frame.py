"""The ROS map and the 3D worlds agree: the same walls, as thick, in the same frame."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from realistic_indoor.io import save
from realistic_indoor.io.world3d import WorldOptions, building_boxes


def _ros_map(path):
    """Occupied pixel centres ``(N, 2)`` of a ROS map, in map coordinates (m), and its resolution."""
    yaml = dict(line.split(": ", 1) for line in path.read_text(encoding="utf-8").splitlines() if ": " in line)
    resolution = float(yaml["resolution"])
    ox, oy, _yaw = (float(v) for v in yaml["origin"].strip("[]").split(","))
    data = path.with_suffix(".pgm").read_bytes()
    header = data.split(b"\n", 3)
    width, height = (int(v) for v in header[1].split())
    image = np.frombuffer(header[3], dtype=np.uint8).reshape(height, width)
    rows, cols = np.nonzero(image == 0)
    x = ox + (cols + 0.5) * resolution
    y = oy + (height - 1 - rows + 0.5) * resolution
    return np.column_stack([x, y]), resolution


@pytest.mark.parametrize("plan", ["office", "slanted"])
@pytest.mark.parametrize("thickness", [0.1, 0.3])
def test_ros_map__occupied_pixels_are_the_3d_wall_boxes(plan, thickness, request, tmp_path):
    b = request.getfixturevalue(plan)
    save(b, tmp_path / "map.yaml", wall_thickness_m=thickness)
    occupied, res = _ros_map(tmp_path / "map.yaml")
    boxes = building_boxes(b, WorldOptions(wall_thickness_m=thickness))
    footprint = shapely.union_all([shapely.Polygon(x.corners()[:4, :2]) for x in boxes if x.kind == "wall"])
    # every wall pixel lies on a box (within the pixel's half diagonal) ...
    assert shapely.contains_xy(footprint.buffer(res * 0.75), occupied[:, 0], occupied[:, 1]).all()
    # ... and every pixel well inside a box is a wall pixel
    inner = footprint.buffer(-res * 0.75)
    cells = np.floor(occupied / res).astype(np.int64)
    grid = set(map(tuple, cells))
    xs, ys = np.meshgrid(
        *(np.arange(lo, hi, res / 2) for lo, hi in zip(inner.bounds[:2], inner.bounds[2:], strict=True))
    )
    probe = np.column_stack([xs.ravel(), ys.ravel()])
    probe = probe[shapely.contains_xy(inner, probe[:, 0], probe[:, 1])]
    assert len(probe) > 0
    assert all(tuple(c) in grid for c in np.floor(probe / res).astype(np.int64))
