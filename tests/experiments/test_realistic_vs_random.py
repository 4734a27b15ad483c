import csv
import json
from pathlib import Path

import pytest
from script_loader import load_script


def _load():
    return load_script("experiments/realistic_vs_random.py")


@pytest.fixture(scope="module")
def small_run(tmp_path_factory):
    pytest.importorskip("stable_baselines3")
    out = tmp_path_factory.mktemp("rvr")
    assert _load().main(["--small", "--out", str(out)]) == 0
    return out


def test_realistic_vs_random__small_run_writes_report_figures_and_raw_results(small_run):
    report = (small_run / "realistic_vs_random.md").read_text()
    for heading in (
        "## Coverage AUC (rank)",
        "## Rankings compared with random maps",
        "## Where the metrics differ",
        "## Transfer of PPO to realistic and real buildings",
    ):
        assert heading in report
    assert "realistic_vs_random.py --small --out" in report  # the command that regenerates it
    for name in (
        "realistic_vs_random.png",
        "realistic_vs_random_curves.png",
        "ppo_random.zip",
        "ppo_realistic.zip",
    ):
        assert (small_run / name).stat().st_size > 0
    rows = list(csv.DictReader((small_run / "realistic_vs_random" / "summary.csv").open()))
    agents = {r["agent"] for r in rows}
    assert agents == {
        "random",
        "wall follower",
        "frontier",
        "utility",
        "structure",
        "PPO (random maps)",
        "PPO (realistic maps)",
    }
    groups = {r["group"] for r in rows}
    assert {"random maps", "offices", "schools", "houses"} <= groups


def test_realistic_vs_random__real_plans_are_a_test_set(small_run, real_plans_dir):
    data = json.loads((small_run / "realistic_vs_random" / "results.json").read_text())
    groups = {e["group"] for e in data["episodes"]}
    assert {"real offices", "real schools"} <= groups
    assert all(Path(p).is_file() for p in data["meta"]["real_plans"])


def test_realistic_vs_random__report_regenerates_byte_for_byte(small_run):
    first = (small_run / "realistic_vs_random.md").read_bytes()
    assert _load().main(["--small", "--out", str(small_run), "--report-only"]) == 0
    assert (small_run / "realistic_vs_random.md").read_bytes() == first


def test_realistic_vs_random__report_only_of_a_small_run_needs_its_folder():
    from realistic_indoor.errors import ConfigError

    with pytest.raises(ConfigError, match="needs --out"):
        _load().main(["--report-only", "--small"])
