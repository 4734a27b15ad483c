"""What a robot knows of its teammates and of the base: poses in its own frame, worked out by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest

from realistic_indoor.envs.observations import POSE_LIMIT_M
from realistic_indoor.teams.observations import observe_team

# robot 0 at the origin facing +x; robot 1 at (1, 2) facing +y; robot 2 far away, facing -x
POSES = np.array([[0.0, 0.0, 0.0], [1.0, 2.0, math.pi / 2], [2000.0, 0.0, math.pi]])
BASE = (-1.0, 0.0)


def _links(pairs, n=3):
    links = np.zeros((n + 1, n + 1), dtype=bool)
    for a, b in pairs:
        links[a, b] = links[b, a] = True
    return links


def test_linked_teammates__in_each_robots_frame():
    links = _links([(0, 1), (1, 2), (0, 3)])  # 0-1-2 a chain; 0 reaches the base (node 3)
    components = np.zeros(4, dtype=np.int64)  # all connected
    mates, base = observe_team(POSES, BASE, links, components)
    assert mates.shape == (3, 2, 5) and mates.dtype == np.float32
    # robot 0 sees robot 1 straight: 1 m ahead, 2 m to the left, turned a quarter left
    assert mates[0, 0] == pytest.approx([1, 1, 1.0, 2.0, math.pi / 2])
    # robot 0 and robot 2 are connected through robot 1, not directly; 2,000 m ahead is clipped
    assert mates[0, 1] == pytest.approx([0, 1, POSE_LIMIT_M, 0.0, math.pi])
    # robot 1 faces +y: robot 0 (1 m to its -x, 2 m to its -y) is 2 m behind and 1 m to its left
    assert mates[1, 0] == pytest.approx([1, 1, -2.0, 1.0, -math.pi / 2], abs=1e-6)
    # robot 2 faces -x: robot 0 is 2,000 m ahead (clipped); heading difference -pi wraps to +-pi
    assert mates[2, 0][:4] == pytest.approx([0, 1, POSE_LIMIT_M, 0.0], abs=1e-4)
    assert abs(mates[2, 0][4]) == pytest.approx(math.pi)
    # the base at (-1, 0): 1 m behind robot 0; robot 1 sees it 2 m behind and 2 m to the left
    assert base[0] == pytest.approx([1, 1, -1.0, 0.0])
    assert base[1] == pytest.approx([0, 1, -2.0, 2.0], abs=1e-6)


def test_unconnected_teammates__only_their_link_flags_and_zeros():
    links = _links([(0, 1)])
    components = np.array([0, 0, 1, 2])  # robot 2 and the base each on their own
    mates, base = observe_team(POSES, BASE, links, components)
    assert mates[0, 1].tolist() == [0, 0, 0, 0, 0]  # robot 0 knows nothing of robot 2
    assert mates[2].tolist() == [[0] * 5, [0] * 5]
    assert base[:, :2].tolist() == [[0, 0]] * 3  # nobody reaches the base
    assert base[0, 2:] == pytest.approx([-1.0, 0.0])  # its position is known from the start


def test_one_robot__no_teammate_rows():
    mates, base = observe_team(POSES[:1], BASE, _links([], n=1), np.array([0, 1]))
    assert mates.shape == (1, 0, 5) and base.shape == (1, 4)
