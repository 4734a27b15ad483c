"""The team environment: PettingZoo's API on every id, the single env's episode for one robot, rules."""

from __future__ import annotations

import hashlib

import gymnasium as gym
import numpy as np
import pytest
from team_buildings import rooms_in_a_row

pytest.importorskip("pettingzoo", reason="the team environments need PettingZoo (the 'teams' extra)")

from pettingzoo.test import api_test, parallel_api_test

import realistic_indoor.envs  # noqa: F401  (registers the ids)
from realistic_indoor import teams
from realistic_indoor.envs import PRESETS
from realistic_indoor.errors import ActionError, ConfigError

AREAS_M2 = {"office": 300.0, "school": 800.0, "house": 100.0, "random": 300.0}
"""Small buildings of each type keep the tests fast."""


def make(env_id, n_robots=2, **kwargs):
    kwargs.setdefault("area_m2", AREAS_M2[PRESETS[env_id].building_type])
    return teams.parallel_env(env_id, n_robots=n_robots, **kwargs)


def random_actions(env, rng):
    return (
        {a: env.action_space(a).sample() for a in env.agents}
        if rng is None
        else {a: rng.uniform(-1, 1, 2).astype(np.float32) for a in env.agents}
    )


@pytest.mark.parametrize("n_robots", [1, 2, 4, 8])
@pytest.mark.parametrize("env_id", sorted(PRESETS))
def test_parallel_api_test__passes_on_every_id(env_id, n_robots):
    parallel_api_test(make(env_id, n_robots, max_steps=15), num_cycles=20)


def test_aec_version__passes_pettingzoo_api_test():
    api_test(teams.env("OfficeExplore-v0", n_robots=2, area_m2=300.0, max_steps=10), num_cycles=15)


@pytest.mark.parametrize("env_id", ["OfficeExplore-v0", "HouseSearch-v0"])
def test_one_robot_without_links__runs_the_single_env_episode(env_id):
    kwargs = {"area_m2": AREAS_M2[PRESETS[env_id].building_type], "max_steps": 60}
    single = gym.make(env_id, **kwargs)
    team = teams.parallel_env(env_id, n_robots=1, comm="none", map_sharing="own", **kwargs)
    obs, info = single.reset(seed=3)
    team_obs, team_info = team.reset(seed=3)
    rng = np.random.default_rng(0)
    for t in range(60):
        mine = team_obs["robot_0"]
        for key, value in obs.items():
            assert np.array_equal(mine[key], value), (t, key)
        assert team_info["robot_0"]["coverage"] == info["coverage"]
        action = rng.uniform(-1, 1, 2).astype(np.float32)
        obs, reward, terminated, truncated, info = single.step(action)
        team_obs, rewards, terms, _truncs, team_info = team.step({"robot_0": action})
        assert rewards["robot_0"] == reward and terms["robot_0"] == terminated
        if terminated or truncated:
            break


def side_by_side(a, b, seed, steps):
    """Reset two team envs with ``seed`` and step both with the same random actions.

    Yields:
        ``((obs_a, info_a), (obs_b, info_b))`` after each step.
    """
    a.reset(seed=seed)
    b.reset(seed=seed)
    rng = np.random.default_rng(seed)
    for _ in range(steps):
        actions = random_actions(a, rng)
        obs_a, _, _, _, info_a = a.step(actions)
        obs_b, _, _, _, info_b = b.step(actions)
        yield (obs_a, info_a), (obs_b, info_b)


def _episode_digest(env, seed, steps=40):
    obs, _ = env.reset(seed=seed)
    rng = np.random.default_rng(seed)
    h = hashlib.sha256()
    for _ in range(steps):
        obs, rewards, *_ = env.step(random_actions(env, rng))
        for agent in sorted(obs):
            for key in sorted(obs[agent]):
                h.update(obs[agent][key].tobytes())
            h.update(np.float64(rewards[agent]).tobytes())
    return h.hexdigest()


def test_same_seed__same_team_episode():
    a = _episode_digest(make("OfficeSearch-v0", 3, comm="wss"), seed=5)
    b = _episode_digest(make("OfficeSearch-v0", 3, comm="wss"), seed=5)
    c = _episode_digest(make("OfficeSearch-v0", 3, comm="wss"), seed=6)
    assert a == b != c


def test_robots__start_apart_and_never_overlap_each_other():
    env = make("OfficeExplore-v0", 4, comm="unlimited", map_sharing="shared")
    env.reset(seed=1)
    radius = env.config.robot.radius_m
    rng = np.random.default_rng(1)
    closest = np.inf
    for _ in range(150):
        env.step({a: np.array([1.0, rng.uniform(-0.3, 0.3)], np.float32) for a in env.agents})
        xy = env.simulation.poses[:, :2]
        gaps = np.hypot(*(xy[:, None] - xy[None]).transpose(2, 0, 1))[np.triu_indices(4, 1)]
        closest = min(closest, gaps.min())
    assert closest > 2 * radius - 0.06  # never deeper than a sub-step's travel (5 cm) and the slop


def test_shared_map__covers_what_the_own_maps_cover_together():
    """The same actions: the shared map's coverage is the union's (the team map of 'own')."""
    shared = make("OfficeExplore-v0", 3, comm="none", map_sharing="shared")
    own = make("OfficeExplore-v0", 3, comm="none", map_sharing="own")
    for (_, info_s), (_, info_o) in side_by_side(shared, own, seed=2, steps=60):
        assert info_s["robot_0"]["coverage"] == info_o["robot_0"]["coverage"]
        assert max(info_o[a]["own_coverage"] for a in info_o) <= info_o["robot_0"]["coverage"]
    assert info_o["robot_0"]["map_cells_sent"] == 0 and info_s["robot_0"]["map_cells_sent"] > 0


def test_comm_sharing__merges_maps_while_linked_and_not_without_links():
    linked = make("OfficeExplore-v0", 3, comm="unlimited", map_sharing="comm")
    apart = make("OfficeExplore-v0", 3, comm="none", map_sharing="comm")
    (obs_l, info_l), (obs_a, info_a) = list(side_by_side(linked, apart, seed=4, steps=40))[-1]
    assert all(info_l[a]["own_coverage"] == info_l[a]["coverage"] for a in info_l)
    assert all(info_a[a]["own_coverage"] < info_a[a]["coverage"] for a in info_a)
    assert info_l["robot_0"]["messages"] > 0 == info_a["robot_0"]["messages"]
    assert obs_l["robot_0"]["teammates"][:, :2].all() and not obs_a["robot_0"]["teammates"].any()
    assert obs_l["robot_0"]["base"][:2].all() and not obs_a["robot_0"]["base"][:2].any()


def test_comm_sharing__the_team_covers_what_every_scan_saw_as_links_come_and_go():
    """Short links split the team and join it again; its coverage stays that of all scans ('own')."""
    links = teams.RangeLinks(range_m=2.0)
    comm = make("OfficeExplore-v0", 4, comm=links, map_sharing="comm")
    own = make("OfficeExplore-v0", 4, comm=links, map_sharing="own")
    groups = set()
    for (_, info_c), (_, info_o) in side_by_side(comm, own, seed=7, steps=150):
        assert info_c["robot_0"]["coverage"] == info_o["robot_0"]["coverage"]
        groups.add(len(set(comm.simulation.maps.robot_map.tolist())))
    assert 1 in groups and max(groups) > 1  # together, and apart
    for agent in info_c:
        assert info_c[agent]["own_coverage"] >= info_o[agent]["own_coverage"]  # merged maps know more


@pytest.mark.parametrize(("comm", "reported"), [("unlimited", 1), ("none", 0)])
def test_search__ends_when_every_victim_is_found_and_counts_the_findings_that_reach_the_base(comm, reported):
    """A victim in the corridor, 2 m ahead of the entrance: found at the start, so the first step ends."""
    env = teams.parallel_env("OfficeSearch-v0", n_robots=2, comm=comm, victims={"n_victims": 1})
    _, infos = env.reset(seed=0, options={"building": rooms_in_a_row(4), "victims": [(2.5, 5.0)]})
    assert infos["robot_0"]["victims_found"] == 1
    _, _, terms, truncs, infos = env.step({a: np.zeros(2, np.float32) for a in env.agents})
    assert all(terms.values()) and not any(truncs.values()) and env.agents == []
    assert infos["robot_1"]["victims_found"] == 1 and infos["robot_1"]["victims_reported"] == reported


def test_state_and_render__show_the_team():
    env = make("OfficeExplore-v0", 3, render_mode="rgb_array")
    env.reset(seed=0)
    state = env.state()
    assert env.state_space.contains(state) and state[3].sum() > 0 and state[0].sum() > 0
    frame = env.render()
    assert frame.ndim == 3 and frame.dtype == np.uint8


@pytest.mark.parametrize(
    "kwargs",
    [
        {"n_robots": 0},
        {"n_robots": teams.MAX_ROBOTS + 1},
        {"comm": "radio"},
        {"map_sharing": "gossip"},
        {"action_type": "frontier"},
        {"robot": {"physics": "pymunk"}},
        {"no_such_field": 1},
    ],
)
def test_bad_settings__get_a_one_line_config_error(kwargs):
    with pytest.raises(ConfigError) as e:
        teams.parallel_env("OfficeExplore-v0", **kwargs)
    assert "\n" not in str(e.value)


def test_bad_actions__get_a_one_line_action_error():
    env = make("OfficeExplore-v0", 2)
    env.reset(seed=0)
    good = np.zeros(2, np.float32)
    for actions in (
        {"robot_0": good},
        {"robot_0": good, "robot_1": good, "robot_7": good},
        {"robot_0": good, "robot_1": np.array([np.nan, 0.0])},
    ):
        with pytest.raises(ActionError) as e:
            env.step(actions)
        assert "\n" not in str(e.value)


@pytest.mark.parametrize(
    ("kwargs", "fix"),
    [
        ({"robot": {"physics": "pymunk"}}, "leave robot physics at 'compiled'"),
        ({"action_type": "waypoint"}, "run macro decisions per robot on the agent's side"),
        ({"extra_observations": ("time_left",)}, "leave extra_observations out"),
        ({"rewards": {"coverage_auc": 1.0}}, "set rewards={'coverage_auc': 0.0}"),
    ],
)
def test_team__what_a_team_cannot_run_is_a_one_line_error_with_the_fix(kwargs, fix):
    with pytest.raises(ConfigError, match=r"^a team cannot run ") as error:
        teams.parallel_env("OfficeExplore-v0", n_robots=2, **kwargs)
    assert str(error.value).endswith(f"; {fix}") and "\n" not in str(error.value)
