"""Evaluating teams: every agent at every team size, the robots column, speed-up and team metrics."""

from __future__ import annotations

import csv
import math

import pytest

pytest.importorskip("pettingzoo", reason="the team environments need PettingZoo (the 'teams' extra)")

from realistic_indoor.cli import main
from realistic_indoor.evaluation import run_evaluation
from realistic_indoor.evaluation.aggregate import add_speedup
from realistic_indoor.evaluation.team_episode import team_info


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture(scope="module")
def team_run(plan_dir, tmp_path_factory):
    out = tmp_path_factory.mktemp("team_eval")
    plan = plan_dir / "a.json"
    evaluation = run_evaluation(
        ["frontier", "coordinated"],
        [f"OfficeExplore-v0:{plan}"],
        episodes=1,
        seed=3,
        workers=1,
        out_dir=out,
        progress=False,
        env_kwargs={"max_steps": 300},
        robots=[1, 2],
    )
    alone = run_evaluation(
        ["frontier"],
        [f"OfficeExplore-v0:{plan}"],
        1,
        3,
        1,
        None,
        False,
        progress=False,
        env_kwargs={"max_steps": 300},
    )
    return out, evaluation, alone.results[0]


def test_robots__every_agent_at_every_team_size_with_a_robots_column(team_run):
    out, _, _ = team_run
    episodes = read_csv(out / "episodes.csv")
    assert [(e["agent"], e["robots"]) for e in episodes] == [
        ("frontier", "1"),
        ("frontier", "2"),
        ("coordinated", "1"),
        ("coordinated", "2"),
    ]
    summary = read_csv(out / "summary.csv")
    assert [(s["agent"], s["robots"]) for s in summary] == [(e["agent"], e["robots"]) for e in episodes]
    assert {"speedup", "efficiency", "messages", "linked_to_base_share"} <= set(summary[0])
    assert (out / "speedup.png").is_file()


def test_robots__a_team_of_one_explores_as_the_robot_alone(team_run):
    _, evaluation, alone = team_run
    team_of_one = evaluation.results[0]
    assert (team_of_one.agent, team_of_one.robots) == ("frontier", 1)
    assert team_of_one.steps == alone.steps
    assert team_of_one.coverage_auc == alone.coverage_auc
    assert team_of_one.path_length_m == alone.path_length_m
    assert team_of_one.time_to_target_s == alone.time_to_target_s or math.isnan(alone.time_to_target_s)


def test_robots__two_robots_drive_further_between_them_and_talk(team_run):
    _, evaluation, _ = team_run
    one, two = evaluation.results[0], evaluation.results[1]
    assert two.robots == 2 and two.messages > one.messages
    assert 0.0 <= two.linked_to_base_share <= 1.0


def test_add_speedup__one_robots_mean_time_over_the_teams():
    rows = [
        {"agent": "a", "group": "g", "robots": 1, "time_to_target_s": 100.0},
        {"agent": "a", "group": "g", "robots": 2, "time_to_target_s": 40.0},
        {"agent": "a", "group": "g", "robots": 4, "time_to_target_s": math.nan},
        {"agent": "b", "group": "g", "robots": 2, "time_to_target_s": 50.0},
    ]
    add_speedup(rows)
    assert [r["speedup"] for r in rows[:2]] == [1.0, 2.5]
    assert rows[1]["efficiency"] == 1.25
    assert math.isnan(rows[2]["speedup"]) and math.isnan(rows[3]["speedup"])


def test_team_info__the_teams_coverage_and_the_robots_sums():
    infos = {
        "robot_0": {"coverage": 0.5, "path_length_m": 3.0, "collisions": 1, "messages": 4},
        "robot_1": {"coverage": 0.5, "path_length_m": 2.5, "collisions": 2, "messages": 4},
    }
    assert team_info(infos) == {"coverage": 0.5, "path_length_m": 5.5, "collisions": 3, "messages": 4}


@pytest.mark.parametrize(
    ("agents", "robots", "message"),
    [
        ("frontier", "0", "team sizes must be integers from 1 to 16, got 0"),
        ("frontier", "1,two", "--robots takes team sizes (integers), comma-separated, got 'two'"),
        ("frontier", "17", "team sizes must be integers from 1 to 16, got 17"),
        ("frontier", "2,2", "team sizes repeat: 2, 2"),
        ("structure", "2", "unknown team agent 'structure'"),
        ("coordinated", None, "'coordinated' is a team agent"),
    ],
)
def test_evaluate_cli__bad_team_input_gets_one_line_and_exit_1(agents, robots, message, tmp_path, capsys):
    argv = [
        "evaluate",
        "--agents",
        agents,
        "--envs",
        "OfficeExplore-v0",
        "--episodes",
        "1",
        "--out",
        str(tmp_path),
    ]
    code = main(argv + ([] if robots is None else ["--robots", robots]))
    err = capsys.readouterr().err.strip()
    assert code == 1
    assert message in err and len(err.splitlines()) == 1 and "Traceback" not in err


def test_make_team_env__env_kwargs_name_the_links_and_the_map_sharing():
    from realistic_indoor.evaluation.tasks import EnvSpec, make_team_env
    from realistic_indoor.teams import NoLinks

    spec = EnvSpec("OfficeExplore-v0", kwargs={"comm": "none", "map_sharing": "own", "area_m2": 300.0})
    env = make_team_env(spec, 2)
    assert isinstance(env.team.links, NoLinks) and env.team.map_sharing == "own"
    assert env.config.source.area_m2 == 300.0
