"""Exact Euclidean distance transform in numba (Meijster et al. 2000; Felzenszwalb & Huttenlocher).

Several times faster than ``scipy.ndimage.distance_transform_edt``, which also builds the
feature transform: the world's distance field is rebuilt with every new building. Private: use
:func:`realistic_indoor.sim.fields.distance_field`.
"""

from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["distance_to_mask"]

_INF = 1e20


def distance_to_mask(obstacle: np.ndarray) -> np.ndarray:
    """Distance (in cells, centre to centre) from every cell to the nearest ``True`` cell.

    Args:
        obstacle: ``(H, W)`` bool array.

    Returns:
        ``(H, W)`` float32 array, 0 on obstacle cells; where there is no obstacle at all, 1e10.
    """
    return _edt(np.ascontiguousarray(obstacle, dtype=np.bool_))


@njit(cache=True, nogil=True)
def _edt(obstacle):  # pragma: no cover - compiled
    h, w = obstacle.shape
    g = np.empty((h, w), dtype=np.float32)  # squared distance to the nearest obstacle in the column
    for c in range(w):
        g[0, c] = 0.0 if obstacle[0, c] else _INF
    for r in range(1, h):  # sweeps row by row: contiguous memory
        for c in range(w):
            g[r, c] = 0.0 if obstacle[r, c] else g[r - 1, c] + 1.0
    for r in range(h - 2, -1, -1):
        for c in range(w):
            g[r, c] = min(g[r, c], g[r + 1, c] + 1.0)
    for r in range(h):
        for c in range(w):
            g[r, c] = g[r, c] * g[r, c] if g[r, c] < _INF else _INF
    out = np.empty((h, w), dtype=np.float32)
    v = np.empty(w, dtype=np.int64)
    z = np.empty(w + 1)
    for r in range(h):  # lower envelope of parabolas along each row
        k = 0
        v[0] = 0
        z[0] = -_INF
        z[1] = _INF
        for q in range(1, w):
            s = _intersection(g, r, q, v[k])
            while s <= z[k]:
                k -= 1
                s = _intersection(g, r, q, v[k])
            k += 1
            v[k] = q
            z[k] = s
            z[k + 1] = _INF
        k = 0
        for q in range(w):
            while z[k + 1] < q:
                k += 1
            out[r, q] = np.sqrt(min((q - v[k]) ** 2 + np.float64(g[r, v[k]]), 1e20))
    return out


@njit(cache=True, nogil=True, inline="always")
def _intersection(g, r, q, p):  # pragma: no cover - compiled
    return ((np.float64(g[r, q]) + q * q) - (np.float64(g[r, p]) + p * p)) / (2.0 * (q - p))
