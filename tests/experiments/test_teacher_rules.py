"""The teacher-rules experiment: its report's arithmetic and a small run against the classical explorer."""

import json
from types import SimpleNamespace

import pytest
from script_loader import load_script


def _load():
    return load_script("experiments/teacher_rules.py")


def test_teacher_rules__report_pairs_each_rule_with_the_references_by_building():
    module = _load()

    def r(rule, seed, auc):
        return SimpleNamespace(agent=f"rule:{rule}", group="houses", seed=seed, coverage_auc=auc)

    results = [
        r("frontier", 900, 0.70), r("frontier", 901, 0.60),
        r("structure", 900, 0.65), r("structure", 901, 0.55),
        r("utility", 900, 0.80), r("utility", 901, 0.60),
    ]  # fmt: skip
    rows = {
        line.split("|")[2].strip(): [c.strip() for c in line.strip("|").split("|")]
        for line in module.analyse(results).splitlines()
        if line.startswith("| houses")
    }
    assert rows["frontier"][2:] == ["2", "0.650", "", "+0.050 [+0.050, +0.050] *"]
    assert rows["structure"][4] == "-0.050 [-0.050, -0.050] *"
    # utility: +0.10 and +0.00 against frontier (mean +0.05, interval from the two), +0.15 / +0.05 against structure
    assert rows["utility"][3] == "0.700"
    assert rows["utility"][4].startswith("+0.050 [+0.000, +0.100]") and "*" not in rows["utility"][4]
    assert rows["utility"][5] == "+0.100 [+0.050, +0.150] *"


def test_teacher_rules__the_frontier_rule_is_the_nearest_frontier_explorer(tmp_path):
    """A small run; its frontier rule's episodes are the classical explorer's, AUC for AUC."""
    from realistic_indoor.evaluation import evaluate

    argv = ["--small", "--out", str(tmp_path), "--rules", "frontier,structure", "--extra", "nearest=1,1,0,0"]
    assert _load().main(argv) == 0
    data = json.loads((tmp_path / "teacher_rules" / "frontier" / "results.json").read_text())
    rule = {e["seed"]: e["coverage_auc"] for e in data["episodes"]}
    # an unregistered rule with the frontier rule's weights drives as it does
    extra = json.loads((tmp_path / "teacher_rules" / "nearest" / "results.json").read_text())
    assert {e["seed"]: e["coverage_auc"] for e in extra["episodes"]} == rule
    classical = evaluate(
        ["frontier"],
        ["HouseExplore-v0"],
        episodes=2,
        seed=900,
        env_kwargs={"max_steps": 60},
        progress=False,
        workers=1,
    )
    assert rule == {r.seed: r.coverage_auc for r in classical}
    assert (tmp_path / "teacher_rules" / "structure" / "results.json").is_file()
    assert "| houses | structure | 2 |" in (tmp_path / "teacher_rules.md").read_text()
    assert "| houses | nearest | 2 |" in (tmp_path / "teacher_rules.md").read_text()
    command = f"teacher_rules.py --small --out {tmp_path} --rules frontier,structure --extra nearest=1,1,0,0`"
    assert command in (tmp_path / "teacher_rules.md").read_text()  # the report says how to redo it
    # the same name with other weights is refused, not read back as if it were the same rule
    from realistic_indoor.errors import ConfigError

    with pytest.raises(ConfigError, match="results of the rule 'nearest' with other weights"):
        _load().main([*argv[:-1], "nearest=3,1,1,0"])
    with pytest.raises(ConfigError, match="results of the rule 'nearest' with other weights"):
        _load().main([*argv[:-1], "nearest=1,1,0,0,1"])  # a heading term is another rule
    # nor read back as if they had run on other seeds, sets or episode settings
    with pytest.raises(ConfigError, match=r"on seeds \[900, 901\] of \['houses'\] .*, not 3 seeds of"):
        _load().main([*argv, "--episodes", "3"])
    with pytest.raises(ConfigError, match=r"not 2 seeds of \['offices', 'houses'\]"):
        _load().main([*argv, "--sets", "houses,offices"])
    full_length = ["--out", str(tmp_path), "--rules", "frontier", "--episodes", "2", "--sets", "houses"]
    with pytest.raises(ConfigError, match=r"\(episode settings \{'max_steps': 60\}\), not 2 seeds"):
        _load().main([*full_length, "--report-only"])
    # the same seeds and sets, named explicitly (a set twice is once), are read back, not run again
    assert _load().main([*argv, "--episodes", "2", "--sets", "houses,houses", "--report-only"]) == 0
    # results saved before the heading term existed (no turn_weight) are read back as its 0
    path = tmp_path / "teacher_rules" / "nearest" / "results.json"
    saved = json.loads(path.read_text())
    del saved["meta"]["weights"]["turn_weight"]
    path.write_text(json.dumps(saved))
    assert _load().main([*argv, "--report-only"]) == 0


def test_teacher_rules__bad_options_are_one_line_errors(tmp_path, capsys):
    from realistic_indoor.cli import run_script

    module = _load()
    for argv, message in (
        (["--workers", "0"], "--workers must be an integer >= 1, not 0"),
        (["--rules", "oracle"], "--rules: unknown ['oracle']"),
        (["--extra", "area=1,2"], "--extra 'area=1,2': give a new name and four to seven numbers"),
        (["--extra", "frontier=1,1,0,0"], "--extra 'frontier=1,1,0,0': give a new name"),
        (["--extra", "area=1,1,0,x"], "NAME=COST,ROOM,LENGTH,GAIN"),
        (["--extra", "area=1,1,0,2", "--extra", "area=1,1,0,3"], "--extra 'area' is given twice"),
        (["--extra", "short=1,1,0,0,0,2,1,5"], "four to seven numbers"),
        (["--episodes", "0"], "--episodes must be an integer >= 1, not 0"),
        (["--sets", "schools,attics"], "--sets: unknown ['attics']; sets: offices, schools, houses"),
        (["--sets", ","], "--sets: unknown [',']; sets: offices, schools, houses"),
    ):
        code = run_script(
            lambda argv=argv: module.main(["--small", "--out", str(tmp_path), *argv]), "teacher_rules"
        )
        err = capsys.readouterr().err.strip()
        assert code != 0 and message in err and "\n" not in err
