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
