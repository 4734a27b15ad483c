"""Simulation: its step finds the victims its sensor sees; without victims it senses none."""

from __future__ import annotations

import numpy as np
import pytest

from realistic_indoor.building import Building, Room
from realistic_indoor.envs.config import EnvConfig
from realistic_indoor.envs.simulation import Simulation
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.victims import VictimConfig, place_victims

RANGE_M = 3.0
VICTIMS = VictimConfig(n_victims=3, sensor_range_m=RANGE_M)


@pytest.fixture
def hall() -> Building:
    """One 10 m x 4 m room and no door: the robot starts at its centre (5, 2), heading +x."""
    room = Room.rectangle("r", "medium", "office", (0.0, 0.0, 10.0, 4.0))
    return Building("office", (room,), (), {"generator": "hand-made"})


def _sim(building: Building, victims: bool = True) -> Simulation:
    config = EnvConfig(victims=VICTIMS)
    sim = Simulation(config, victims=victims)
    sim.load(building)
    return sim


def test_step__reports_the_victim_the_sensor_comes_to_see(hall):
    sim = _sim(hall)
    rng = np.random.default_rng(0)
    assert sim.world.start_pose == pytest.approx((5.0, 2.0, 0.0))
    # 2.5 m ahead (in view from the start), 4.5 m ahead (in view once within 3 m), 4 m behind
    ahead, far, behind = (7.5, 2.0), (9.5, 2.0), (1.0, 2.0)
    sim.reset(rng, victims_xy=np.array([ahead, far, behind]))
    assert sim.victims.found.tolist() == [True, False, False]
    assert sim.victims.in_view.tolist() == [True, False, False]

    reported = [sim.step(1.0, 0.0, rng).victims_found for _ in range(10)]

    xs = [x for x, _ in sim.trajectory[1:]]
    first_near = next(k for k, x in enumerate(xs) if far[0] - x <= RANGE_M)  # straight ahead
    assert reported == [int(k == first_near) for k in range(10)]
    assert sim.victims.found.tolist() == [True, True, False]
    assert sim.victims.in_view.tolist() == [True, True, False]


def test_step__without_victims_senses_none(hall):
    sim = _sim(hall, victims=False)
    rng = np.random.default_rng(0)
    sim.reset(rng)
    outcome = sim.step(1.0, 0.0, rng)
    assert sim.victims is None and outcome.victims_found is None
    with pytest.raises(ConfigError, match="without victims"):
        sim.reset(rng, victims_xy=np.zeros((3, 2)))


def test_reset__draws_victims_after_the_first_scan(hall):
    """Placement draws from the generator after the first scan's noise (the recorded order)."""
    sim, rng = _sim(hall), np.random.default_rng(3)
    sim.reset(rng)
    explore, rng_explore = _sim(hall, victims=False), np.random.default_rng(3)
    explore.reset(rng_explore)
    assert np.array_equal(sim.scan.ranges_m, explore.scan.ranges_m)
    assert np.array_equal(sim.victims.xy, place_victims(explore.world, rng_explore, VICTIMS))
    assert rng.random() == rng_explore.random()
