"""The rescue score: doorways and crossings from a building's doors, reached within 1 m, points summed."""

from __future__ import annotations

import math

import numpy as np
import pytest

from realistic_indoor.building.building import Building
from realistic_indoor.building.door import Door
from realistic_indoor.building.room import Room
from realistic_indoor.errors import ConfigError
from realistic_indoor.evaluation.rescue_score import (
    Checkpoints,
    CheckpointTracker,
    RescueScoreConfig,
    checkpoints,
    rescue_score,
)


def corridor_building() -> Building:
    """Two corridors and a hall in a row, an office off the first corridor, a store off the hall."""
    rooms = [
        Room.rectangle("c1", "corridor", "corridor", (0, 0, 10, 2)),
        Room.rectangle("c2", "corridor", "corridor", (10, 0, 20, 2)),
        Room.rectangle("h", "hall", "lobby", (20, 0, 26, 6)),
        Room.rectangle("o", "medium", "office", (0, 2, 5, 7)),
        Room.rectangle("s", "small", "storage", (20, 6, 23, 9)),
    ]
    doors = [
        Door("d1", "o", "c1", 2.5, 2.0),  # a doorway into a room
        Door("d2", "c1", "c2", 10.0, 1.0),  # corridor meets corridor: a crossing
        Door("d3", "c2", "h", 20.0, 1.0),  # corridor opens into the hall: a crossing
        Door("d4", "s", "h", 21.5, 6.0),  # a doorway, the room on side a
        Door("d5", "c1", None, 0.0, 1.0),  # the entrance: neither
    ]
    return Building("office", rooms, doors)


def test_checkpoints__inside_doors_into_rooms_are_doorways_openings_between_corridors_and_halls_crossings():
    points = checkpoints(corridor_building())
    assert points.doorways.tolist() == [[2.5, 2.0], [21.5, 6.0]]
    assert points.crossings.tolist() == [[10.0, 1.0], [20.0, 1.0]]


def test_tracker__a_checkpoint_counts_once_a_robot_comes_within_reach_and_stays_counted():
    points = Checkpoints(np.array([[0.0, 0.0], [5.0, 0.0]]), np.array([[0.0, 10.0]]))
    tracker = CheckpointTracker(points, reach_m=1.0)
    tracker.add(np.array([[0.6, 0.8, 0.0], [5.0, 1.01, 3.0]]))  # 1.0 m and 1.01 m away
    assert tracker.doorways.tolist() == [True, False]
    assert tracker.doorways_share == 0.5 and tracker.crossings_share == 0.0
    tracker.add(np.array([[50.0, 50.0, 0.0], [0.0, 9.5, 0.0]]))
    assert tracker.doorways.tolist() == [True, False] and tracker.crossings.tolist() == [True]
    assert tracker.share == pytest.approx(2 / 3)


def test_tracker__a_building_without_checkpoints_has_no_share_of_either_and_nothing_to_reach():
    tracker = CheckpointTracker(Checkpoints(np.zeros((0, 2)), np.zeros((0, 2))), reach_m=1.0)
    tracker.add(np.zeros((2, 3)))
    assert math.isnan(tracker.doorways_share) and math.isnan(tracker.crossings_share)
    assert tracker.share == 0.0


def test_score__ten_a_victim_reported_minus_five_a_wrong_report_fifty_for_every_checkpoint():
    assert rescue_score(3, 0.5) == 30.0 + 25.0
    assert rescue_score(3, 0.5, wrong_reports=1) == 50.0
    assert rescue_score(0, 1.0) == 50.0
    points = RescueScoreConfig(victim_points=20.0, wrong_report_points=0.0, exploration_points=100.0)
    assert rescue_score(2, 0.25, wrong_reports=4, config=points) == 40.0 + 25.0


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("wrong_report_points", 5.0),
        ("victim_points", -1.0),
        ("reach_m", 0.0),
        ("exploration_points", math.nan),
    ],
)
def test_score_config__points_of_the_wrong_sign_or_no_reach_are_one_line_errors(field, value):
    with pytest.raises(ConfigError, match=f"RescueScoreConfig.{field}") as error:
        RescueScoreConfig(**{field: value})
    assert "\n" not in str(error.value)


def test_team_episode__the_score_is_the_victims_reported_and_the_checkpoints_the_robots_reached():
    pytest.importorskip("pettingzoo", reason="the team environments need PettingZoo (the 'teams' extra)")
    from realistic_indoor import teams
    from realistic_indoor.evaluation import EnvSpec, EpisodeTask, run_episode
    from realistic_indoor.evaluation.team_episode import run_team_episode

    spec = EnvSpec("HouseSearch-v0", kwargs={"max_steps": 800})
    result = run_team_episode(EpisodeTask("coordinated", spec, seed=1, robots=2))
    env = teams.parallel_env("HouseSearch-v0", n_robots=2, max_steps=800)
    env.reset(seed=1)
    points = checkpoints(env.simulation.world.building)
    n_doorways, n_crossings = len(points.doorways), len(points.crossings)
    assert n_doorways > 3
    reached = result.doorways_reached * n_doorways + (
        result.crossings_reached * n_crossings if n_crossings else 0
    )
    assert reached == pytest.approx(round(reached))  # whole checkpoints
    assert 0 < result.doorways_reached <= 1
    share = reached / (n_doorways + n_crossings)
    assert result.rescue_score == pytest.approx(10 * result.victims_reported + 50 * share)
    alone = run_episode(EpisodeTask("frontier", spec, seed=1))
    assert math.isnan(alone.rescue_score) and math.isnan(alone.doorways_reached)
