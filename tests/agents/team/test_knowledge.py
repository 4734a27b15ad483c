"""What robots know of each other: maps laid on one another, and shared as the links allow."""

from __future__ import annotations

import math

import numpy as np

from realistic_indoor.agents.team.knowledge import TeamFrames, TeamMaps, groups, share_victims
from realistic_indoor.navigation.own_map import OwnMap
from realistic_indoor.navigation.victims import VictimTracker
from realistic_indoor.sim.mapping import MAPPED_UNKNOWN

BEAMS = np.linspace(-math.pi / 2, math.pi / 2, 19)


def scanned(pose, range_m=3.0):
    """A map that saw free floor ``range_m`` around ``pose`` (no wall returned)."""
    own = OwnMap(BEAMS, max_range_m=range_m)
    own.integrate(pose, np.full(len(BEAMS), range_m))
    return own


def known_points(own):
    rows, cols = np.nonzero(own.state != MAPPED_UNKNOWN)
    return {tuple(p) for p in np.round(own.to_world(rows, cols), 3)}


def test_merge__the_merged_map_knows_what_both_knew_and_a_second_merge_adds_nothing():
    a, b = scanned((0.0, 0.0, 0.0)), scanned((30.0, -25.0, math.pi))  # b's grid must grow to hold a
    union = known_points(a) | known_points(b)
    gained = b.merge(a)
    assert gained == len(known_points(a) - known_points(scanned((30.0, -25.0, math.pi))))
    assert known_points(b) == union
    assert b.merge(a) == 0


def test_team_maps__comm_shares_within_groups_copies_on_a_split_and_never_with_own():
    maps = TeamMaps(3, "comm", lambda i: scanned((3.0 * i, 0.0, 0.0)))
    assert maps.update(np.array([0, 0, 1])) == [1]
    assert maps.maps[0] is maps.maps[1] is not maps.maps[2]
    assert known_points(maps.maps[0]) == known_points(scanned((0.0, 0.0, 0.0))) | known_points(
        scanned((3.0, 0.0, 0.0))
    )
    before = known_points(maps.maps[0])
    assert maps.update(np.array([0, 1, 2])) == [1]
    assert maps.maps[0] is not maps.maps[1] and known_points(maps.maps[1]) == before
    own = TeamMaps(2, "own", lambda i: scanned((0.0, 0.0, 0.0)))
    assert own.update(np.array([0, 0])) == [] and own.maps[0] is not own.maps[1]
    shared = TeamMaps(2, "shared", lambda i: scanned((0.0, 0.0, 0.0)))
    assert shared.maps[0] is shared.maps[1]


def test_groups__from_the_connected_column_of_the_teammates_observation():
    def obs(connected):
        rows = np.zeros((len(connected), 5), dtype=np.float32)
        rows[:, 1] = connected
        return {"teammates": rows}

    agents = ["robot_0", "robot_1", "robot_2", "robot_3"]
    observations = {
        "robot_0": obs([0, 1, 0]),
        "robot_1": obs([0, 0, 1]),
        "robot_2": obs([1, 0, 0]),
        "robot_3": obs([0, 1, 0]),
    }
    assert groups(observations, agents).tolist() == [0, 1, 0, 1]


def test_team_frames__poses_in_robot_0s_odometry_frame():
    frames = TeamFrames(np.array([[5.0, 5.0, math.pi / 2], [5.0, 6.0, math.pi / 2]]))
    assert np.allclose(frames.offsets[1], (1.0, 0.0, 0.0))  # one metre ahead of robot 0
    assert np.allclose(frames.to_team(1, np.array([2.0, 1.0, 0.5])), (3.0, 1.0, 0.5))


def tracker(*points, visited=False):
    t = VictimTracker(sensor_range_m=3.0, merge_m=1.0)
    t.positions = np.array(points, dtype=float).reshape(-1, 2)
    t.visited = np.full(len(t.positions), visited)
    return t


def test_share_victims__a_teammate_s_victim_is_known_as_visited_and_one_outside_the_group_is_not():
    a = tracker((0.0, 0.0))  # robot 0 detected a victim at the origin
    b = tracker((0.5, 0.5))  # robot 1 detected the same one, 0.71 m off: the same victim
    c = tracker((10.0, 0.0))  # robot 2 detected another
    d = tracker()  # robot 3, alone in its group
    share_victims([a, b, c, d], np.array([0, 0, 0, 1]))
    assert a.positions.tolist() == [[0.0, 0.0], [10.0, 0.0]] and a.visited.tolist() == [False, True]
    assert b.positions.tolist() == [[0.5, 0.5], [10.0, 0.0]] and b.visited.tolist() == [False, True]
    assert c.positions.tolist() == [[10.0, 0.0], [0.0, 0.0]] and c.visited.tolist() == [False, True]
    assert len(d.positions) == 0
    share_victims([a, b, c, d], np.array([0, 0, 0, 1]))  # a second time adds nothing
    assert len(a.positions) == len(b.positions) == len(c.positions) == 2
