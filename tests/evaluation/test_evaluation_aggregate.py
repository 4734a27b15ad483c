import math

import numpy as np
import pytest

from realistic_indoor.evaluation import bootstrap_mean, summarize, wilson
from realistic_indoor.evaluation.aggregate import mean_curve
from realistic_indoor.evaluation.episode import EpisodeResult


def _result(agent, coverage, reached, time_s, seed=0, group="g"):
    return EpisodeResult(
        agent=agent,
        env=group,
        group=group,
        seed=seed,
        steps=100,
        max_steps=100,
        dt_s=0.2,
        final_coverage=coverage,
        coverage_auc=coverage / 2,
        reached_target=reached,
        time_to_target_s=time_s,
        path_to_target_m=math.nan,
        path_length_m=50.0,
        collisions=1,
        episode_return=1.0,
        victims_total=0,
        victims_found=0,
        time_to_first_victim_s=math.nan,
        time_to_all_victims_s=math.nan,
    )


def test_bootstrap_mean__interval_holds_the_mean_and_shrinks_with_n():
    rng = np.random.default_rng(0)
    small = bootstrap_mean(rng.normal(1.0, 1.0, 10))
    large = bootstrap_mean(rng.normal(1.0, 1.0, 1000))
    assert small.low < small.mean < small.high
    assert large.high - large.low < (small.high - small.low) / 5
    assert large.low < 1.0 < large.high
    assert bootstrap_mean([1.0, 2.0, 4.0]) == bootstrap_mean([1.0, 2.0, 4.0])  # fixed seed


def test_bootstrap_mean__leaves_out_nan_and_handles_edge_cases():
    est = bootstrap_mean([1.0, math.nan, 3.0])
    assert est.n == 2 and est.mean == 2.0
    assert math.isnan(bootstrap_mean([math.nan]).mean)
    assert bootstrap_mean([5.0]).low == bootstrap_mean([5.0]).high == 5.0


def test_wilson__known_values():
    est = wilson(8, 10)
    assert est.mean == 0.8
    assert est.low == pytest.approx(0.4902, abs=1e-3) and est.high == pytest.approx(0.9433, abs=1e-3)
    assert wilson(0, 5).low == pytest.approx(0.0, abs=1e-12) and wilson(5, 5).high == pytest.approx(1.0)


def test_summarize__one_row_per_agent_and_group():
    results = [_result("a", 0.9, 1, 100.0, s) for s in range(3)] + [
        _result("b", 0.5, 0, math.nan, s) for s in range(3)
    ]
    rows = summarize(results)
    assert [(r["agent"], r["episodes"]) for r in rows] == [("a", 3), ("b", 3)]
    assert rows[0]["final_coverage"] == pytest.approx(0.9) and rows[0]["reached_target"] == 1.0
    assert rows[0]["time_to_target_s"] == 100.0
    assert math.isnan(rows[1]["time_to_target_s"])  # no episode got there
    assert math.isnan(rows[0]["victims_found_share"])  # exploration has no victims


def test_mean_curve__holds_short_curves_at_their_last_value():
    mean, low, high = mean_curve([[0.0, 0.5, 1.0], [0.0, 0.5]])
    assert mean.tolist() == [0.0, 0.5, 0.75]
    assert np.all(low <= mean) and np.all(mean <= high)
    assert mean_curve([[0.0, 0.5, 1.0], [0.0, 0.5]], length=5)[0].tolist() == [0.0, 0.5, 0.75, 0.75, 0.75]
