import json
import math

import pytest

from realistic_indoor.cli import main
from realistic_indoor.errors import ConfigError
from realistic_indoor.evaluation import evaluate, make_tasks, parse_envs, read_results, run_tasks


def test_parse_envs__ids_plans_and_folders(plan_dir):
    specs = parse_envs(
        ["OfficeExplore-v0", f"OfficeSearch-v0:{plan_dir}", f"HouseExplore-v0:{plan_dir / 'a.json'}"]
    )
    assert [s.label for s in specs] == [
        "OfficeExplore-v0",
        "OfficeSearch-v0:a",
        "OfficeSearch-v0:b",
        "HouseExplore-v0:a",
    ]
    assert specs[1].group == specs[2].group == f"OfficeSearch-v0:{plan_dir.name}"
    with pytest.raises(ConfigError, match="unknown environment id 'MazeExplore-v0'"):
        parse_envs(["MazeExplore-v0"])
    with pytest.raises(ConfigError, match="neither a file nor a folder"):
        parse_envs(["OfficeExplore-v0:no/such/plan.xml"])


def test_make_tasks__same_seeds_for_every_agent(plan_dir):
    envs = parse_envs([f"OfficeExplore-v0:{plan_dir / 'a.json'}"])
    tasks = make_tasks(["random", "frontier"], envs, episodes=3, seed=10)
    assert [(t.agent, t.seed) for t in tasks] == [
        (a, s) for a in ("random", "frontier") for s in (10, 11, 12)
    ]
    with pytest.raises(ConfigError, match="episodes"):
        make_tasks(["random"], envs, episodes=0)


def test_run_tasks__processes_give_the_results_of_one_process(plan_dir):
    envs = parse_envs([f"OfficeExplore-v0:{plan_dir}"], {"max_steps": 40})
    tasks = make_tasks(["frontier", "random"], envs, episodes=2)
    serial = run_tasks(tasks, workers=1, progress=False)
    parallel = run_tasks(tasks, workers=2, progress=False)

    def same(r):  # everything but the wall-clock time; repr makes NaN equal to NaN
        return repr(r.to_dict() | {"agent_ms_per_step": 0})

    assert [same(r) for r in serial] == [same(r) for r in parallel]


def test_run_tasks__bad_agent_fails_before_any_episode(plan_dir):
    envs = parse_envs([f"OfficeExplore-v0:{plan_dir}"])
    with pytest.raises(ConfigError, match="unknown agent"):
        run_tasks(make_tasks(["frontier", "astar"], envs, 1), workers=1, progress=False)


def test_evaluate__writes_csv_json_and_figures(tmp_path, plan_dir):
    results = evaluate(
        ["frontier", "random"],
        [f"OfficeExplore-v0:{plan_dir}"],
        episodes=2,
        workers=1,
        out_dir=tmp_path,
        progress=False,
        env_kwargs={"max_steps": 30},
    )
    assert len(results) == 8
    for name in ("episodes.csv", "summary.csv", "results.json", "coverage_time.png", "coverage_distance.png"):
        assert (tmp_path / name).stat().st_size > 0
    episodes, meta = read_results(tmp_path / "results.json")
    assert meta["episodes"] == 2 and len(episodes) == 8
    assert all(math.isnan(e.time_to_target_s) for e in episodes)  # 30 steps: never at 90%
    assert [e.coverage_t for e in episodes] == [r.coverage_t for r in results]
    summary = json.loads((tmp_path / "results.json").read_text())["summary"]
    assert {(row["agent"], row["episodes"]) for row in summary} == {("frontier", 4), ("random", 4)}
    lines = (tmp_path / "episodes.csv").read_text().splitlines()
    assert len(lines) == 9 and lines[0].startswith(
        "agent,env,group,seed,steps,max_steps,final_coverage,coverage_auc"
    )


def test_cli_evaluate__prints_a_summary(tmp_path, plan_dir, capsys):
    code = main(
        [
            "evaluate",
            "--agents",
            "frontier,random",
            "--envs",
            f"OfficeExplore-v0:{plan_dir / 'a.json'}",
            "--episodes",
            "2",
            "--max-steps",
            "30",
            "--workers",
            "1",
            "--quiet",
            "--no-figures",
            "--out",
            str(tmp_path),
        ]
    )
    out = capsys.readouterr().out
    assert code == 0
    assert "final_coverage" in out and "frontier" in out and "OfficeExplore-v0:a" in out
    assert not (tmp_path / "coverage_time.png").exists()


def test_cli_evaluate__ray_missing_names_the_install(tmp_path, plan_dir, capsys):
    try:
        import ray  # noqa: F401

        pytest.skip("ray is installed")
    except ImportError:
        pass
    code = main(
        [
            "evaluate",
            "--agents",
            "random",
            "--envs",
            f"OfficeExplore-v0:{plan_dir / 'a.json'}",
            "--episodes",
            "1",
            "--ray",
            "--quiet",
            "--out",
            str(tmp_path),
        ]
    )
    assert code == 1
    assert "pip install ray" in capsys.readouterr().err


def test_cli_evaluate__bad_env_kwargs(tmp_path, capsys):
    code = main(["evaluate", "--agents", "random", "--envs", "OfficeExplore-v0", "--env-kwargs", "{area"])
    assert code == 1 and "--env-kwargs is not valid JSON" in capsys.readouterr().err
