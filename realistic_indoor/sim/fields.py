"""Fields over a grid of cells: the exact Euclidean distance to the nearest obstacle cell.

The world's clearance and the raycaster's skip field come from :func:`distance_field`, and so
does an agent's clearance on its own map: one distance transform for the simulator and the
agents. It works on any ``(H, W)`` grid of square cells, with or without a :class:`World`.
"""

from __future__ import annotations

import numpy as np

from realistic_indoor.checks import require_positive
from realistic_indoor.sim._edt import distance_to_mask

__all__ = ["distance_field"]


def distance_field(obstacle: np.ndarray, resolution_m: float = 1.0) -> np.ndarray:
    """Distance from the centre of every cell to the centre of the nearest obstacle cell.

    Exact (Meijster et al. 2000), as ``scipy.ndimage.distance_transform_edt(~obstacle)`` and
    several times faster: about 5 ms per million cells of a building's raster, 13 where obstacles
    are scattered (1% of the cells at random).

    Args:
        obstacle: ``(H, W)`` bool array, ``True`` on obstacle cells.
        resolution_m: Side of a cell (m); the default 1 gives distances in cells.

    Returns:
        ``(H, W)`` float32 array (m, or cells at the default resolution), 0 on obstacle cells; a
        new array. Without any obstacle cell, every cell holds 1e10 cells times ``resolution_m``.
    """
    require_positive("distance_field", "resolution_m", resolution_m, "m")
    dist = distance_to_mask(obstacle)
    if resolution_m != 1.0:
        dist *= np.float32(resolution_m)
    return dist
