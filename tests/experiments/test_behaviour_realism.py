import csv
import json
import math
import warnings
from pathlib import Path

import pytest
from script_loader import load_script

AGENTS = ("wall", "frontier", "structure")


def _load():
    return load_script("experiments/behaviour_realism.py")


def _run(argv):
    """The script as its command line runs it: (exit code, its stderr lines are checked by capsys)."""
    from realistic_indoor.cli import run_script

    module = _load()
    return run_script(lambda: module.main(argv), "behaviour_realism.py")


def _small_office(doors_to=("a", "b")):
    """A 10 m x 6 m office (60 m2): a corridor with an entrance and two offices off it.

    Only the offices named in ``doors_to`` get a door: without ``b``'s, its 20 m2 are cut off.
    """
    from realistic_indoor.building import Building, Door, Room

    rooms = (
        Room.rectangle("c", "corridor", "corridor", (0, 0, 10, 2)),
        Room.rectangle("a", "medium", "office", (0, 2, 5, 6)),
        Room.rectangle("b", "medium", "office", (5, 2, 10, 6)),
    )
    doors = {
        "a": Door("d1", "a", "c", 2.5, 2.0, 0.9, 0.0),
        "b": Door("d2", "b", "c", 7.5, 2.0, 0.9, 0.0),
    }
    entrance = Door("e1", "c", None, 0.0, 1.0, 1.2, math.pi / 2)
    return Building("office", rooms, (*(doors[r] for r in doors_to), entrance), {"source": "hand-made"})


@pytest.fixture(scope="module")
def plans(tmp_path_factory):
    """Three office plans (a generated 300 m2 one, a hand-made 60 m2 one, the same with a room cut
    off), a broken file and a house."""
    from realistic_indoor.generator import generate_from, make_generator
    from realistic_indoor.io import save

    folder = tmp_path_factory.mktemp("plans")
    save(generate_from(make_generator("office", 300.0), 7), folder / "office-a.json")
    save(_small_office(), folder / "small-office.json")
    save(_small_office(doors_to=("a",)), folder / "split-office.json")
    save(generate_from(make_generator("house", 120.0), 3), folder / "house.json")
    (folder / "broken.json").write_text("{ not a plan")
    return folder


@pytest.fixture(scope="module")
def small_run(plans, tmp_path_factory):
    from realistic_indoor.validator.plan_sets import SkippedPlanWarning

    out = tmp_path_factory.mktemp("behaviour")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert _load().main([str(plans), "--small", "--plans", "3", "--out", str(out)]) == 0
    skipped = [str(w.message) for w in caught if issubclass(w.category, SkippedPlanWarning)]
    return out, skipped


def _csv(path):
    return list(csv.DictReader(path.open()))


def test_small_run__one_summary_row_per_agent_and_set(small_run):
    out, _ = small_run
    rows = _csv(out / "summary.csv")
    assert sorted((r["agent"], r["set"]) for r in rows) == sorted(
        (a, s) for a in AGENTS for s in ("real", "twins")
    )
    assert {r["episodes"] for r in rows} == {"3"}
    for r in rows:
        assert float(r["coverage_auc_low"]) <= float(r["coverage_auc"]) <= float(r["coverage_auc_high"])


def test_small_run__paired_difference_is_twin_minus_real_by_plan(small_run):
    out, _ = small_run
    episodes = _csv(out / "episodes.csv")
    auc = {(e["agent"], e["set"], e["plan"]): float(e["coverage_auc"]) for e in episodes}
    paired = {r["agent"]: r for r in _csv(out / "paired.csv")}
    assert set(paired) == set(AGENTS)
    for agent in AGENTS:
        diff = {
            p: auc[(agent, "twins", p)] - auc[(agent, "real", p)]
            for p in ("office-a", "small-office", "split-office")
        }
        row = paired[agent]
        assert row["pairs"] == "3"
        assert float(row["difference"]) == pytest.approx(sum(diff.values()) / 3, abs=1e-5)
        assert min(diff.values()) - 1e-5 <= float(row["difference_low"]) <= float(row["difference"])
        assert float(row["difference"]) <= float(row["difference_high"]) <= max(diff.values()) + 1e-5
        assert int(row["twin_higher"]) == sum(d > 0 for d in diff.values())
        # without the cut-off split office: two pairs, whose bootstrap interval spans their two values
        connected = [diff["office-a"], diff["small-office"]]
        assert row["connected_pairs"] == "2"
        assert float(row["connected_difference"]) == pytest.approx(sum(connected) / 2, abs=1e-5)
        assert float(row["connected_difference_low"]) == pytest.approx(min(connected), abs=1e-5)
        assert float(row["connected_difference_high"]) == pytest.approx(max(connected), abs=1e-5)


def test_small_run__episodes_have_the_same_step_limit_and_steps_per_area(small_run):
    out, _ = small_run
    episodes = _csv(out / "episodes.csv")
    assert len(episodes) == 3 * 2 * 3  # agents x sets x plans
    assert {e["max_steps"] for e in episodes} == {"60"}  # --small's limit, for plans and twins alike
    for e in episodes:
        if e["reached_90"] == "1":
            expected = float(e["steps_to_90"]) / (float(e["reachable_m2"]) / 100.0)
            assert float(e["steps_to_90_per_100m2"]) == pytest.approx(expected, rel=1e-5)
        else:
            assert e["steps_to_90_per_100m2"] == ""


def test_small_run__bad_plans_are_skipped_named_and_counted(small_run):
    out, warned = small_run
    assert any("broken.json" in w for w in warned)
    assert any("house.json" in w and "its type is house, not office" in w for w in warned)
    data = json.loads((out / "behaviour_realism.json").read_text())
    assert sorted(Path(s["source"]).name for s in data["skipped"]) == ["broken.json", "house.json"]
    assert data["meta"]["plan_files"] == 5
    report = (out / "behaviour_realism.md").read_text()
    assert "(5 plan files; 2 left out)" in report
    assert "broken.json" in report and "house.json" in report


def test_small_run__area_below_the_generator_is_clamped_and_reported(small_run):
    out, _ = small_run
    data = json.loads((out / "behaviour_realism.json").read_text())
    pairs = {p["name"]: p for p in data["plans"]}
    assert set(pairs) == {"office-a", "small-office", "split-office"}
    small = pairs["small-office"]
    assert small["clamped"] is True
    assert small["plan_area_m2"] == pytest.approx(60.0)  # 10 m x 6 m
    assert small["twin_area_m2"] == pytest.approx(250.0, rel=0.05)  # the office generator's minimum
    assert pairs["office-a"]["clamped"] is False
    assert pairs["office-a"]["twin_area_m2"] == pytest.approx(pairs["office-a"]["plan_area_m2"], rel=0.02)
    assert "clamped `small-office`: 60 m² plan" in (out / "behaviour_realism.md").read_text()


def test_small_run__a_start_cut_off_from_part_of_the_floor_is_reported(small_run):
    out, _ = small_run
    data = json.loads((out / "behaviour_realism.json").read_text())
    pairs = {p["name"]: p for p in data["plans"]}
    split = pairs["split-office"]
    # the corridor (20 m2) and office a (20 m2) of 60 m2: two thirds, less the walls' raster cells
    assert split["plan_reachable_m2"] / split["plan_area_m2"] == pytest.approx(2 / 3, abs=0.05)
    assert split["cut_off"] is True
    assert pairs["small-office"]["plan_reachable_m2"] / 60.0 == pytest.approx(1.0, abs=0.06)
    assert pairs["small-office"]["cut_off"] is False
    report = (out / "behaviour_realism.md").read_text()
    assert "cut off `split-office`" in report
    assert "Without the 1 cut-off pair (`split-office`):" in report


def test_small_run__writes_report_figure_twins_and_raw_results(small_run, plans):
    out, _ = small_run
    report = (out / "behaviour_realism.md").read_text()
    for heading in (
        "## Coverage AUC",
        "## Steps to 90% coverage per 100 m² of floor",
        "## What it shows",
        "## Per plan",
    ):
        assert heading in report
    assert f"behaviour_realism.py {plans} --small --plans 3 --out {out}" in report
    for label in ("wall follower", "nearest frontier", "structure-aware"):
        assert f"| {label} |" in report
    assert (out / "behaviour_realism.png").stat().st_size > 0
    assert sorted(p.name for p in (out / "twins").iterdir()) == [
        "office-a.json",
        "small-office.json",
        "split-office.json",
    ]
    raw = json.loads((out / "evaluation" / "results.json").read_text())
    assert {e["group"] for e in raw["episodes"]} == {"real", "twins"}


def test_small_run__report_regenerates_byte_for_byte(small_run):
    out, _ = small_run
    first = (out / "behaviour_realism.md").read_bytes()
    assert _load().main(["--report-only", "--out", str(out)]) == 0
    assert (out / "behaviour_realism.md").read_bytes() == first


def test_small_run_without_plans_makes_its_own(tmp_path):
    assert _load().main(["--small", "--out", str(tmp_path)]) == 0
    rows = _csv(tmp_path / "summary.csv")
    assert len(rows) == 6
    assert len(list((tmp_path / "plans").glob("*.json"))) == 2


def test_empty_folder__one_line_error(tmp_path, capsys):
    empty = tmp_path / "empty"
    empty.mkdir()
    assert _run([str(empty), "--out", str(tmp_path / "out")]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert err[0].startswith("behaviour_realism.py: error:") and "no plans there" in err[0]


def test_folder_without_plans_of_the_type__one_line_error(plans, tmp_path, capsys):
    assert _run([str(plans / "house.json"), "--out", str(tmp_path)]) == 1
    err = [line for line in capsys.readouterr().err.splitlines() if "error:" in line]
    assert len(err) == 1 and "none of its 1 plans is a usable office plan" in err[0]


def test_strict_stops_at_the_unreadable_plan(plans, tmp_path, capsys):
    assert _run([str(plans), "--small", "--strict", "--out", str(tmp_path)]) == 1
    err = capsys.readouterr().err
    assert "error:" in err and "broken.json" in err
    assert not (tmp_path / "behaviour_realism.md").exists()


# -- the analysis, on made-up episodes ---------------------------------------------------------------


def _result(agent, env, auc, reached_s=math.nan):
    from realistic_indoor.evaluation import EpisodeResult

    nan = math.nan
    return EpisodeResult(
        agent, env, env.split(":")[0], 0, 100, 100, 0.2, 0.5, auc, int(reached_s == reached_s),
        reached_s, nan, 10.0, 0, 0.0, 0, 0, nan, nan,
    )  # fmt: skip


def _pairs():
    from realistic_indoor.evaluation.twins import PlanPair

    return [
        PlanPair("a", "a.xml", "twins/a.json", 400.0, 404.0, False, 0),
        PlanPair("b", "b.xml", "twins/b.json", 200.0, 250.0, True, 1),
    ]


def test_analysis__paired_difference_and_means_worked_by_hand():
    from realistic_indoor.evaluation.twins import episode_rows, paired_rows, summary_rows

    results = [
        _result("wall", "real:a", 0.2),
        _result("wall", "real:b", 0.4),
        _result("wall", "twin:a", 0.5),
        _result("wall", "twin:b", 0.6),
    ]
    rows = episode_rows(results, _pairs())
    (paired,) = paired_rows(rows, {"wall": "wall follower"})
    # twin - real: 0.3 and 0.2, mean 0.25; both twins higher
    assert paired["pairs"] == 2
    assert paired["difference"] == pytest.approx(0.25)
    assert paired["real"] == pytest.approx(0.3) and paired["twins"] == pytest.approx(0.55)
    assert paired["difference_low"] == pytest.approx(0.2) and paired["difference_high"] == pytest.approx(0.3)
    assert paired["twin_higher"] == 2
    summary = summary_rows(rows, {"wall": "wall follower"})
    assert [(r["set"], r["episodes"]) for r in summary] == [("real", 2), ("twins", 2)]
    assert summary[0]["coverage_auc"] == pytest.approx(0.3)


def test_analysis__steps_to_90_per_100m2_worked_by_hand():
    from realistic_indoor.evaluation.twins import episode_rows, summary_rows

    results = [
        _result("frontier", "real:a", 0.7, reached_s=40.0),  # 200 steps of 0.2 s on 400 m2: 50 per 100 m2
        _result("frontier", "real:b", 0.6),  # never reached 90%
        _result("frontier", "twin:a", 0.7, reached_s=80.8),  # 404 steps on 404 m2: 100 per 100 m2
        _result("frontier", "twin:b", 0.7, reached_s=50.0),  # 250 steps on 250 m2: 100 per 100 m2
    ]
    rows = episode_rows(results, _pairs())
    by = {(r["set"], r["plan"]): r for r in rows}
    assert by[("real", "a")]["steps_to_90"] == 200
    assert by[("real", "a")]["steps_to_90_per_100m2"] == pytest.approx(50.0)
    assert math.isnan(by[("real", "b")]["steps_to_90_per_100m2"])
    summary = {r["set"]: r for r in summary_rows(rows, {"frontier": "nearest frontier"})}
    assert math.isnan(summary["real"]["steps_to_90_per_100m2_median"])  # half never got there
    assert summary["real"]["reached_90"] == 1
    assert summary["twins"]["steps_to_90_per_100m2_median"] == pytest.approx(100.0)


@pytest.mark.parametrize(
    ("values", "expected"),
    [
        ([50.0, 100.0, math.nan], 100.0),
        ([50.0, 100.0, 150.0, math.nan], 125.0),
        ([50.0, math.nan], math.nan),
        ([], math.nan),
    ],
)
def test_censored_median__not_reached_counts_as_slowest(values, expected):
    from realistic_indoor.evaluation.twins import censored_median

    assert censored_median(values) == pytest.approx(expected, nan_ok=True)


def test_a_plan_is_read_once_for_the_study_its_check_and_its_episodes(plans, monkeypatch):
    """Reading twice would repeat a real plan's repair warnings (and the time to read it)."""
    import realistic_indoor.validator.plan_sets as plan_sets
    from realistic_indoor.evaluation import readable_envs
    from realistic_indoor.evaluation.tasks import make_env
    from realistic_indoor.evaluation.twins import PlanPair, read_plans, twin_specs

    calls = []
    read = plan_sets.read_plan
    monkeypatch.setattr(plan_sets, "read_plan", lambda path, **kw: calls.append(path) or read(path, **kw))
    copy = plans.parent / "read-once" / "office-a.json"
    copy.parent.mkdir(exist_ok=True)
    copy.write_bytes((plans / "office-a.json").read_bytes())
    (real,), _, _ = read_plans(copy, "office")
    pair = PlanPair("office-a", real.path, real.path, 300.0, 300.0, False, 0)
    spec = twin_specs([pair], "OfficeExplore-v0", 10)[0]
    readable_envs([spec])
    make_env(spec).close()
    # the study may name the file relative to the working folder; it is one file, read once
    assert [Path(c).resolve() for c in calls] == [copy.resolve()]


def test_analysis__steps_per_reachable_floor_and_cut_off_pairs_left_out_of_connected():
    from realistic_indoor.evaluation.twins import PlanPair, episode_rows, paired_rows

    pairs = [
        PlanPair("a", "a.xml", "twins/a.json", 400.0, 404.0, False, 0, 380.0, 400.0),  # 95% and 99% reachable
        PlanPair("b", "b.xml", "twins/b.json", 200.0, 250.0, True, 1, 50.0, 240.0),  # the plan's start: 25%
    ]
    assert [p.cut_off for p in pairs] == [False, True]
    results = [
        _result("wall", "real:a", 0.2, reached_s=38.0),  # 190 steps on 380 reachable m2: 50 per 100 m2
        _result("wall", "real:b", 0.9),
        _result("wall", "twin:a", 0.5),
        _result("wall", "twin:b", 0.6),
    ]
    rows = episode_rows(results, pairs)
    assert rows[0]["steps_to_90_per_100m2"] == pytest.approx(50.0)
    assert [r["cut_off"] for r in rows] == [False, True, False, True]
    (paired,) = paired_rows(rows, {"wall": "wall follower"})
    assert paired["pairs"] == 2 and paired["difference"] == pytest.approx(0.0)  # +0.3 and -0.3
    assert paired["connected_pairs"] == 1 and paired["connected_difference"] == pytest.approx(0.3)


PLANS = ("office-a", "small-office", "split-office")
"""The usable office plans of the fixture, in file order."""


@pytest.fixture(scope="module")
def two_twin_run(plans, tmp_path_factory):
    out = tmp_path_factory.mktemp("behaviour2")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        argv = [str(plans), "--small", "--plans", "3", "--twins", "2", "--out", str(out)]
        assert _load().main(argv) == 0
    return out


def test_two_twins_per_plan__each_plan_once_its_twins_averaged_in_the_pairs(two_twin_run):
    out = two_twin_run
    episodes = _csv(out / "episodes.csv")
    for agent in AGENTS:
        mine = [e for e in episodes if e["agent"] == agent]
        assert sorted(e["plan"] for e in mine if e["set"] == "real") == list(PLANS)
        twins = sorted((e["plan"], e["twin"]) for e in mine if e["set"] == "twins")
        assert twins == [(p, f"{p}_{k}") for p in PLANS for k in (0, 1)]
    assert sorted(f.name for f in (out / "twins").iterdir()) == [
        f"{p}_{k}.json" for p in PLANS for k in (0, 1)
    ]
    auc = {(e["agent"], e["set"], e["twin"] or e["plan"]): float(e["coverage_auc"]) for e in episodes}
    paired = {r["agent"]: r for r in _csv(out / "paired.csv")}
    for agent in AGENTS:
        diff = [
            (auc[(agent, "twins", f"{p}_0")] + auc[(agent, "twins", f"{p}_1")]) / 2 - auc[(agent, "real", p)]
            for p in PLANS
        ]
        assert paired[agent]["pairs"] == "3"
        assert float(paired[agent]["difference"]) == pytest.approx(sum(diff) / 3, abs=1e-5)
        assert paired[agent]["connected_pairs"] == "2"  # the split office's plan is cut off
        assert float(paired[agent]["connected_difference"]) == pytest.approx(sum(diff[:2]) / 2, abs=1e-5)
    summary = {(r["agent"], r["set"]): r["episodes"] for r in _csv(out / "summary.csv")}
    assert {summary[(a, "real")] for a in AGENTS} == {"3"}
    assert {summary[(a, "twins")] for a in AGENTS} == {"6"}
    report = (out / "behaviour_realism.md").read_text()
    assert "Real plans: 3 office plans" in report and "2 generated office buildings per plan" in report
    assert "| office-a_1 |" in report and "each plan's twins (their mean) minus the plan" in report
    assert "in 1 of the 3 plans or their twins" in report
    assert "Without the 1 cut-off plan (`split-office`)" in report


def test_twins_per_plan_under_one__one_line_error(plans, tmp_path, capsys):
    code = _run([str(plans), "--small", "--twins", "0", "--out", str(tmp_path / "out")])
    err = capsys.readouterr().err.strip().splitlines()
    assert code != 0 and len(err) == 1 and "twins_per_plan must be an integer >= 1, got 0" in err[0]


def test_small_run__one_twin_per_plan_keeps_the_one_twin_wording(small_run):
    report = (small_run[0] / "behaviour_realism.md").read_text()
    assert "- Twins: one generated office building per plan with the plan's floor area" in report
    assert "each plan's twin minus the plan" in report and "cut-off pair" in report


def test_behaviour_realism__report_only_of_a_small_run_needs_its_folder():
    from realistic_indoor.errors import ConfigError

    with pytest.raises(ConfigError, match="needs --out"):
        _load().main(["--report-only", "--small"])
