import json
from types import SimpleNamespace

import pytest
from script_loader import load_script


def _load():
    return load_script("experiments/learned_explorer.py")


def test_learned_explorer__report_pairs_episodes_by_building_and_start():
    """The report's arithmetic on hand-made results: means, paired differences, stars."""
    module = _load()

    def r(agent, env, seed, auc):
        return SimpleNamespace(agent=agent, env=env, group="offices", seed=seed, coverage_auc=auc)

    results = [
        r("learned", "o", 1, 0.80), r("learned", "o", 2, 0.70),
        r("frontier", "o", 1, 0.75), r("frontier", "o", 2, 0.65),
        r("utility", "o", 1, 0.80), r("utility", "o", 2, 0.70),
        r("structure", "o", 1, 0.90), r("structure", "o", 2, 0.60),
    ]  # fmt: skip
    meta = {"command": "c", "commit": "x", "model": "m", "episodes": 2, "seed": 1000, "sets": ["offices"]}
    row = next(line for line in module.analyse(results, meta).splitlines() if line.startswith("| offices"))
    cells = [c.strip() for c in row.strip("|").split("|")]
    assert cells[1] == "2"
    assert cells[2:6] == ["0.750", "0.700", "0.750", "0.750"]
    assert cells[6] == "+0.050 [+0.050, +0.050] *"  # +0.05 on both buildings: apart from 0
    assert cells[7] == "+0.000 [+0.000, +0.000]"
    assert cells[8].startswith("+0.000 [-0.100, +0.100]") and "*" not in cells[8]


@pytest.mark.slow
def test_learned_explorer__small_run_writes_results_and_report(tmp_path):
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    assert _load().main(["--small", "--out", str(tmp_path)]) == 0
    data = json.loads((tmp_path / "learned_explorer" / "results.json").read_text())
    agents = {e["agent"] for e in data["episodes"]}
    assert agents == {"learned", "frontier", "utility", "structure"}
    assert "| houses | 2 |" in (tmp_path / "learned_explorer.md").read_text()
