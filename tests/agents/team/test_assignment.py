"""Burgard's discounted utility and the Hungarian assignment, on numbers worked out by hand."""

from __future__ import annotations

import numpy as np
import pytest

from realistic_indoor.agents.team.coordinated import CoordinatedConfig, frontier_utility
from realistic_indoor.agents.team.hungarian import assign
from realistic_indoor.errors import ConfigError


def test_frontier_utility__loses_the_chance_a_teammate_sees_it_from_its_goal():
    points = np.array([[0.0, 0.0], [5.0, 0.0], [20.0, 0.0], [10.0, 0.0]])
    assert np.allclose(frontier_utility(points, [], 10.0), [1, 1, 1, 1])
    assert np.allclose(frontier_utility(points, [(0.0, 0.0)], 10.0), [0.0, 0.5, 1.0, 1.0])
    assert np.allclose(frontier_utility(points, [(0.0, 0.0), (5.0, 0.0)], 10.0), [-0.5, -0.5, 1.0, 0.5])


def test_assign__minimises_the_total_cost_with_distinct_frontiers():
    # Robot 0 is nearer both frontiers, but robot 1 is far from frontier 1: 1 + 2 beats 2 + 10.
    assert assign(np.array([[2.0, 1.0], [2.0, 10.0]])).tolist() == [1, 0]
    costs = np.array([[1.0, 1.5, 9.0, 4.0], [1.2, 1.1, 9.0, 4.0], [1.0, 1.0, 1.0, 4.0]])
    choice = assign(costs)
    assert len(set(choice.tolist())) == 3
    assert choice.tolist() == [0, 1, 2]


def test_assign__with_fewer_frontiers_than_robots_every_robot_gets_one():
    choice = assign(np.array([[1.0], [2.0], [np.inf]]))
    assert choice.tolist() == [0, 0, 0]
    assert assign(np.array([[3.0, np.inf], [1.0, 5.0]])).tolist() == [0, 1]


def test_coordinated_config__refuses_bad_weights():
    with pytest.raises(ConfigError, match="cost_weight"):
        CoordinatedConfig(cost_weight=0.0)
    with pytest.raises(ConfigError, match="visibility_m"):
        CoordinatedConfig(visibility_m=-1.0)
