"""The overlap of a team's views: the share of what the robots saw that more than one saw."""

from __future__ import annotations

import numpy as np

from realistic_indoor.evaluation.overlap import ViewOverlap
from realistic_indoor.sim.lidar import LidarConfig
from realistic_indoor.sim.mapping import MAPPED_FREE

LIDAR = LidarConfig()


def free_cells(own):
    return int(np.count_nonzero(own.state == MAPPED_FREE))


def test_overlap__same_view_is_all_overlap_and_far_apart_views_none():
    scans = np.full((3, LIDAR.n_beams), 3.0, dtype=np.float32)  # walls 3 m away all round
    same = ViewOverlap(2, LIDAR)
    same.add(np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]), scans[:2])
    assert same.share() == 1.0
    apart = ViewOverlap(3, LIDAR)
    apart.add(np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [40.0, -30.0, 1.0]]), scans)
    a, c = free_cells(apart.maps[0]), free_cells(apart.maps[2])
    assert apart.share() == a / (a + c)
    far = ViewOverlap(2, LIDAR)
    far.add(np.array([[0.0, 0.0, 0.0], [40.0, -30.0, 1.0]]), scans[:2])
    assert far.share() == 0.0
