"""Evaluations that survive bad plans, keep finished episodes, resume, and refuse bad --out folders."""

import json
import math

import pytest

from realistic_indoor.cli import main
from realistic_indoor.errors import ConfigError
from realistic_indoor.evaluation import (
    EnvSpec,
    make_tasks,
    parse_envs,
    read_results,
    readable_envs,
    run_evaluation,
)
from realistic_indoor.evaluation import runner as runner_module
from realistic_indoor.evaluation.episode import run_episode as real_run_episode
from realistic_indoor.evaluation.outputs import LOG_NAME, EpisodeLog, finished_episodes
from realistic_indoor.validator.plan_sets import SkippedPlanWarning

BROKEN_REASON = "malformed XML at line 1, column 1: no element found"


@pytest.fixture
def messy_dir(tmp_path, small_office, tiny_office):
    """Two good generated plans and an empty ``broken.xml``, in sorted order a.json, b.json, broken.xml."""
    from realistic_indoor.io import save

    folder = tmp_path / "plans"
    save(small_office, folder / "a.json")
    save(tiny_office, folder / "b.json")
    (folder / "broken.xml").write_text("")
    return folder


def _evaluate_argv(plans, out, *more):
    return [
        "evaluate",
        "--agents",
        "random",
        "--envs",
        f"OfficeExplore-v0:{plans}",
        "--episodes",
        "1",
        "--max-steps",
        "50",
        "--quiet",
        "--no-figures",
        "--out",
        str(out),
        *more,
    ]


def test_cli_evaluate__folder_with_a_broken_plan_runs_the_good_ones(messy_dir, tmp_path, capsys):
    """The issue's done-when: both good plans run, broken.xml is named, exit 0 (1 under --strict)."""
    out = tmp_path / "out"
    assert main(_evaluate_argv(messy_dir, out)) == 0
    err = capsys.readouterr().err.splitlines()
    broken = messy_dir / "broken.xml"
    assert f"realistic-indoor: warning: skipped {broken}: {BROKEN_REASON}" in err
    assert err[-1] == "skipped 1 of 3 plans: broken.xml (listed in results.json under meta.skipped)"
    episodes, meta = read_results(out / "results.json")
    assert sorted(e.env for e in episodes) == ["OfficeExplore-v0:a", "OfficeExplore-v0:b"]
    assert meta["skipped"] == [{"source": str(broken), "reason": BROKEN_REASON}]
    assert meta["envs"] == ["OfficeExplore-v0:a", "OfficeExplore-v0:b"]
    assert len((out / LOG_NAME).read_text().splitlines()) == 2

    assert main(_evaluate_argv(messy_dir, tmp_path / "strict", "--strict")) == 1
    err = capsys.readouterr().err
    assert err == f"realistic-indoor evaluate: error: {broken}: {BROKEN_REASON}\n"
    assert not (tmp_path / "strict" / LOG_NAME).exists()


def test_cli_evaluate__default_workers_as_in_the_issue(messy_dir, tmp_path, capsys, monkeypatch):
    """The command of the issue verbatim (processes, no --quiet), run in a temporary folder."""
    monkeypatch.chdir(tmp_path)
    argv = ["evaluate", "--agents", "random", "--envs", f"OfficeExplore-v0:{messy_dir}"]
    assert main([*argv, "--episodes", "1", "--max-steps", "50", "--no-figures"]) == 0
    assert "broken.xml" in capsys.readouterr().err
    episodes, _meta = read_results(tmp_path / "runs" / "evaluation" / "results.json")
    assert len(episodes) == 2


def test_readable_envs__skips_unreadable_plans_and_plans_without_rooms(messy_dir):
    from realistic_indoor.building import Building
    from realistic_indoor.io import save

    save(Building("office", ()), messy_dir / "empty.json")
    specs = parse_envs(["OfficeExplore-v0", f"OfficeExplore-v0:{messy_dir}"])
    with pytest.warns(SkippedPlanWarning) as caught:
        kept, skipped = readable_envs(specs)
    assert [s.label for s in kept] == ["OfficeExplore-v0", "OfficeExplore-v0:a", "OfficeExplore-v0:b"]
    assert [(s.source, s.reason) for s in skipped] == [
        (str(messy_dir / "broken.xml"), BROKEN_REASON),
        (str(messy_dir / "empty.json"), "the plan has no rooms"),
    ]
    assert len(caught) == 2
    with (
        pytest.warns(SkippedPlanWarning),
        pytest.raises(ConfigError, match="none of the 1 plans can be used"),
    ):
        readable_envs(parse_envs([f"OfficeExplore-v0:{messy_dir / 'broken.xml'}"]))


def test_parse_envs__folders_are_read_recursively_with_unique_labels(tmp_path, small_office):
    from realistic_indoor.io import save

    save(small_office, tmp_path / "x" / "a.json")
    save(small_office, tmp_path / "x" / "sub" / "a.json")
    save(small_office, tmp_path / "x" / "sub" / "c.json")
    (tmp_path / "x" / ".hidden.json").write_text("{")
    labels = [s.label for s in parse_envs([f"OfficeExplore-v0:{tmp_path / 'x'}"])]
    assert labels == ["OfficeExplore-v0:a", "OfficeExplore-v0:sub/a", "OfficeExplore-v0:c"]


def _interrupt_after(monkeypatch, finished: int) -> list:
    """Make the in-process runner finish ``finished`` episodes, then raise KeyboardInterrupt."""
    calls = []

    def run_episode(task):
        calls.append(task)
        if len(calls) > finished:
            raise KeyboardInterrupt
        return real_run_episode(task)

    monkeypatch.setattr(runner_module, "run_episode", run_episode)
    return calls


def _run(plan_dir, out, **options):
    return run_evaluation(
        ["random", "frontier"],
        [f"OfficeExplore-v0:{plan_dir / 'a.json'}"],
        episodes=2,
        workers=1,
        out_dir=out,
        figures=False,
        progress=False,
        env_kwargs={"max_steps": 30},
        **options,
    )


def _comparable(result) -> dict:
    """An episode's numbers without the agent's wall-clock thinking time."""
    data = result.to_dict()
    data.pop("agent_ms_per_step")
    return {k: (None if isinstance(v, float) and math.isnan(v) else v) for k, v in data.items()}


def test_evaluate__interrupted_run_keeps_finished_episodes_and_resumes(plan_dir, tmp_path, monkeypatch):
    fresh = _run(plan_dir, tmp_path / "fresh")
    out = tmp_path / "out"
    calls = _interrupt_after(monkeypatch, finished=3)
    with pytest.raises(KeyboardInterrupt):
        _run(plan_dir, out)
    assert len(calls) == 4  # 3 finished, the 4th interrupted
    lines = (out / LOG_NAME).read_text().splitlines()
    assert [(json.loads(x)["task"]["agent"], json.loads(x)["task"]["seed"]) for x in lines] == [
        ("random", 0),
        ("random", 1),
        ("frontier", 0),
    ]
    assert not (out / "results.json").exists()

    calls = _interrupt_after(monkeypatch, finished=99)
    resumed = _run(plan_dir, out, resume=True)
    assert [(t.agent, t.seed) for t in calls] == [("frontier", 1)]  # only the missing episode runs
    assert resumed.resumed == 3
    assert [_comparable(r) for r in resumed.results] == [_comparable(r) for r in fresh.results]
    episodes, meta = read_results(out / "results.json")
    assert len(episodes) == 4 and meta["resumed"] == 3
    assert len((out / LOG_NAME).read_text().splitlines()) == 4


def test_finished_episodes__ignores_a_torn_last_line_and_other_episodes(plan_dir, tmp_path):
    envs = parse_envs([f"OfficeExplore-v0:{plan_dir / 'a.json'}"], {"max_steps": 30})
    done = _run(plan_dir, tmp_path).results
    with (tmp_path / LOG_NAME).open("a") as f:
        f.write('{"task": {"agent": "random", "env": "Offi')  # cut by an interrupt
    tasks = make_tasks(["frontier", "wall"], envs, 3)  # frontier seeds 0-2, wall seeds 0-2
    found = finished_episodes(tmp_path, tasks)
    assert sorted(found) == [0, 1]  # frontier seeds 0 and 1 ran; seed 2 and the wall agent did not
    assert found[0].coverage_t == done[2].coverage_t
    log = EpisodeLog(tmp_path, append=True)
    log.write(tasks[2], done[3])
    log.close()
    assert finished_episodes(tmp_path, tasks)[2].seed == done[3].seed  # the torn line was ended first


def test_finished_episodes__other_settings_are_refused(plan_dir, tmp_path):
    _run(plan_dir, tmp_path)
    other = make_tasks(
        ["random"], parse_envs([f"OfficeExplore-v0:{plan_dir / 'a.json'}"], {"max_steps": 40}), 1
    )
    with pytest.raises(ConfigError, match=r"max_steps': 30}.*now \{'max_steps': 40}.*use a new --out folder"):
        finished_episodes(tmp_path, other)


def test_cli_evaluate__out_that_is_a_file_is_refused_before_any_episode(
    messy_dir, tmp_path, capsys, monkeypatch
):
    calls = _interrupt_after(monkeypatch, finished=99)
    target = tmp_path / "results.txt"
    target.write_text("keep me")
    assert main(_evaluate_argv(messy_dir, target)) == 1
    assert capsys.readouterr().err == (
        f"realistic-indoor evaluate: error: --out {target}: {target} is a file, not a folder\n"
    )
    assert calls == [] and target.read_text() == "keep me"


def test_cli_evaluate__earlier_results_need_resume_or_overwrite(plan_dir, tmp_path, capsys, monkeypatch):
    argv = _evaluate_argv(plan_dir / "a.json", tmp_path, "--workers", "1")
    assert main(argv) == 0
    capsys.readouterr()
    calls = _interrupt_after(monkeypatch, finished=99)
    assert main(argv) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert f"--out {tmp_path} holds the results of an earlier run (episodes.jsonl, episodes.csv" in err
    assert "add --resume to continue it, --overwrite to replace it, or choose a new --out folder" in err
    assert main([*argv, "--resume"]) == 0
    assert calls == []  # the one episode was done
    assert "resumed: 1 of 1 episodes taken from the earlier run" in capsys.readouterr().err
    assert main([*argv, "--overwrite"]) == 0
    assert len(calls) == 1
    assert len((tmp_path / LOG_NAME).read_text().splitlines()) == 1


def test_cli_evaluate__interrupt_says_how_to_resume(plan_dir, tmp_path, capsys, monkeypatch):
    _interrupt_after(monkeypatch, finished=1)
    argv = _evaluate_argv(plan_dir / "a.json", tmp_path, "--workers", "1", "--episodes", "3")  # the last wins
    assert main(argv) == 130
    err = capsys.readouterr().err
    assert f"finished episodes are kept in {tmp_path / LOG_NAME}; add --resume" in err
    assert len((tmp_path / LOG_NAME).read_text().splitlines()) == 1


def test_cli_evaluate__default_out_is_an_ignored_run_folder():
    from realistic_indoor.cli import build_parser

    args = build_parser().parse_args(["evaluate", "--agents", "random", "--envs", "OfficeExplore-v0"])
    assert args.out == "runs/evaluation"


def test_plot_coverage__a_failed_write_keeps_the_previous_figure(plan_dir, tmp_path, monkeypatch):
    import matplotlib.figure

    from realistic_indoor.evaluation.figures import plot_coverage

    results = _run(plan_dir, None).results
    target = tmp_path / "coverage_time.png"
    target.write_bytes(b"previous figure")

    def savefig(self, path, **kwargs):
        with open(path, "wb") as f:
            f.write(b"half a pic")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", savefig)
    with pytest.raises(OSError, match="No space left"):
        plot_coverage(results, target)
    assert target.read_bytes() == b"previous figure"
    assert [p.name for p in tmp_path.iterdir()] == ["coverage_time.png"]


def test_run_evaluation__env_specs_without_plans_skip_nothing(tmp_path):
    evaluation = run_evaluation(
        ["random"],
        [EnvSpec("OfficeExplore-v0", kwargs={"max_steps": 5})],
        episodes=1,
        workers=1,
        progress=False,
    )
    assert evaluation.skipped == [] and evaluation.plans == 0 and len(evaluation.results) == 1
