import math

import numpy as np
import pytest

from realistic_indoor.evaluation import EnvSpec, EpisodeTask, run_episode


def test_run_episode__metrics_agree_with_the_episode(small_office):
    env = EnvSpec("OfficeExplore-v0", kwargs={"building": small_office, "max_steps": 400}, label="small")
    r = run_episode(EpisodeTask("frontier", env, seed=0, curve_every_steps=5, curve_every_m=1.0))
    assert r.agent == "frontier" and r.env == "small" and r.group == "small"
    assert r.reached_target == 1 and r.final_coverage >= 0.9
    assert r.time_to_target_s == pytest.approx(r.steps * r.dt_s)  # exploration ends at the target
    assert r.path_to_target_m == pytest.approx(r.path_length_m)
    assert r.victims_total == 0 and math.isnan(r.time_to_first_victim_s)
    assert len(r.coverage_t) == r.steps // 5 + 1 and r.curve_dt_s == pytest.approx(1.0)
    assert np.all(np.diff(r.coverage_t) >= 0)
    assert len(r.coverage_d) == math.floor(r.path_length_m) + 1
    assert np.all(np.diff(r.coverage_d) >= 0) and r.coverage_d[-1] <= r.final_coverage
    assert r.agent_ms_per_step > 0
    assert r.max_steps == 400
    assert 0 < r.coverage_auc < r.final_coverage
    # a plan at the start, then one at least every few dozen steps, never one per step
    assert 1 < r.decisions < r.steps / 3


def test_run_episode__agents_that_choose_no_goals_report_no_decisions(small_office):
    env = EnvSpec("OfficeExplore-v0", kwargs={"building": small_office, "max_steps": 30})
    assert run_episode(EpisodeTask("random", env, seed=0)).decisions == 0


def test_coverage_auc__holds_the_final_coverage_to_the_step_limit():
    from realistic_indoor.evaluation.episode import _auc

    assert _auc(np.array([0.0, 0.5, 1.0]), 2) == pytest.approx(0.5)
    assert _auc(np.array([0.0, 1.0]), 3) == pytest.approx(3 / 4)  # 0, 1, then held at 1 twice


def test_run_episode__victim_times(small_office):
    env = EnvSpec("OfficeSearch-v0", kwargs={"building": small_office, "max_steps": 800})
    r = run_episode(EpisodeTask("frontier", env, seed=2))
    assert r.victims_total == 3 and r.victims_found == 3
    assert len(r.victim_times_s) == 3 and r.victim_times_s == sorted(r.victim_times_s)
    assert r.time_to_first_victim_s == r.victim_times_s[0]
    assert r.time_to_all_victims_s == r.victim_times_s[-1] == pytest.approx(r.steps * r.dt_s)
    assert r.reached_target in (0, 1)


def test_run_episode__unreached_target_gives_nan(small_office):
    env = EnvSpec("OfficeExplore-v0", kwargs={"building": small_office, "max_steps": 20})
    r = run_episode(EpisodeTask("random", env, seed=0))
    assert r.steps == 20 and r.reached_target == 0
    assert r.coverage_auc <= r.final_coverage
    assert math.isnan(r.time_to_target_s) and math.isnan(r.path_to_target_m)
