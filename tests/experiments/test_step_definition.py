import json

import pytest
from script_loader import load_script


def _load():
    return load_script("experiments/step_definition.py")


@pytest.fixture(scope="module")
def small_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("step_definition")
    assert _load().main(["--small", "--out", str(out)]) == 0
    return out


def test_step_definition__env_specs_put_each_definition_over_the_runs_settings():
    module = _load()
    specs = {s.group: s for s in module.env_specs(module.SMALL, "37 beams, 0.1 m cells")}
    offices = specs["offices / 37 beams, 0.1 m cells"]
    assert offices.env_id == "OfficeExplore-v0"
    assert offices.kwargs == {
        "max_steps": 60,
        "lidar": {"n_beams": 37},
        "world": {"resolution_m": 0.1},
        "area_m2": 300.0,
    }
    default = {s.group: s for s in module.env_specs(module.FULL, "default")}
    assert default["schools / default"].kwargs == {}


def test_step_definition__every_agent_meets_the_same_seeds_under_every_definition(small_run):
    data = json.loads((small_run / "step_definition" / "results.json").read_text())
    seen = {}
    for e in data["episodes"]:
        seen.setdefault(e["group"], set()).add((e["agent"], e["seed"]))
    assert len(seen) == 3 * 3  # sets x definitions
    pairs = {frozenset(v) for v in seen.values()}
    assert pairs == {
        frozenset(
            (a, s) for a in ("random", "wall follower", "frontier", "utility", "structure") for s in (0, 1)
        )
    }


def test_step_definition__report_names_command_sections_and_regenerates_byte_for_byte(small_run):
    report = (small_run / "step_definition.md").read_text()
    for heading in ("## Coverage AUC", "## Rankings by coverage AUC", "## Where the time went"):
        assert heading in report
    assert "step_definition.py --small --out" in report
    assert "| offices | frontier |" in report
    assert "Kendall tau to the default's" in report
    assert _load().main(["--report-only", "--out", str(small_run)]) == 0
    assert (small_run / "step_definition.md").read_text() == report


def _result(agent, group, seed, auc):
    from realistic_indoor.evaluation import EpisodeResult

    nan = float("nan")
    return EpisodeResult(
        agent=agent, env=group, group=group, seed=seed, steps=100, max_steps=100, dt_s=0.2,
        final_coverage=auc, coverage_auc=auc, reached_target=0, time_to_target_s=nan,
        path_to_target_m=nan, path_length_m=1.0, collisions=0, episode_return=0.0, victims_total=0,
        victims_found=0, time_to_first_victim_s=nan, time_to_all_victims_s=nan, agent_ms_per_step=2.0,
    )  # fmt: skip


def test_step_definition__report_gives_lighter_minus_default_per_seed_and_the_rankings():
    module = _load()
    definitions = {"default": {}, "light": {"lidar": {"n_beams": 37}}}
    results = []
    for seed, (frontier, wall) in enumerate([(0.8, 0.5), (0.6, 0.3)]):  # default
        results += [_result("frontier", "offices / default", seed, frontier)]
        results += [_result("wall follower", "offices / default", seed, wall)]
    for seed, (frontier, wall) in enumerate([(0.7, 0.5), (0.5, 0.9)]):  # light: frontier 0.1 lower
        results += [_result("frontier", "offices / light", seed, frontier)]
        results += [_result("wall follower", "offices / light", seed, wall)]
    meta = {
        "command": "x",
        "episodes": 2,
        "definitions": definitions,
        "wall_s": {"default": 3.0},
        "workers": 1,
    }
    report = module.analyse(results, meta)
    # frontier: -0.1 on both seeds, an interval of one value that excludes 0
    assert "| offices | frontier | 0.700 | 0.600 | -0.100 [-0.100, -0.100] * |" in report
    # wall follower: 0.0 and +0.6, mean +0.3; the interval holds 0, no star
    row = next(line for line in report.splitlines() if line.startswith("| offices | wall follower |"))
    assert row.startswith("| offices | wall follower | 0.400 | 0.700 | +0.300 [")
    assert not row.endswith("* |")
    assert "- **offices, default**: frontier > wall follower" in report
    assert "- **offices, light**: wall follower > frontier (Kendall tau to the default's: -1.00)" in report
    assert "| default | 400 | 200 | 1 | 3 |" in report  # 4 episodes of 100 steps, 2 ms each


def test_step_definition__report_only_of_a_small_run_needs_its_folder():
    from realistic_indoor.errors import ConfigError

    with pytest.raises(ConfigError, match="needs --out"):
        _load().main(["--report-only", "--small"])
