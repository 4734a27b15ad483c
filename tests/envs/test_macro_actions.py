"""Frontier macro actions (``action_type="frontier"``): a policy chooses among candidate goals and the
explorers' navigator drives there.

Expected values come from outside the macro code: the nearest-frontier agent run in the same
building with primitive actions (a policy that always chooses candidate 0 must drive exactly as it
does), and the coverage AUC computed from each primitive step's coverage by its definition (the
mean of the coverage after steps 0..max_steps, held after an early end).
"""

from __future__ import annotations

import warnings

import gymnasium as gym
import numpy as np
import pytest
from env_helpers import make_env
from gymnasium.utils.env_checker import check_env, data_equivalence

from realistic_indoor.agents import make_agent
from realistic_indoor.envs.macro import CANDIDATE_FEATURES
from realistic_indoor.errors import ActionError, ConfigError

CASES = [
    ("OfficeExplore-v0", {"area_m2": 600.0}, 3),
    ("HouseSearch-v0", {"victims": {"n_victims": 2}}, 5),
]


def _frontier_episode(env_id, kwargs, seed, n_steps):
    """The nearest-frontier agent's primitive actions and the coverage after each step."""
    env = gym.make(env_id, **kwargs)
    agent = make_agent("frontier", env)
    obs, info = env.reset(seed=seed)
    agent.reset()
    actions, coverage = [], [info["coverage"]]
    for _ in range(n_steps):
        action = agent.act(obs, info)
        actions.append(np.asarray(action).copy())
        obs, _, terminated, truncated, info = env.step(action)
        coverage.append(info["coverage"])
        if terminated or truncated:
            break
    return actions, coverage


def _recording(env):
    """Record every primitive action the macro environment sends to its robot."""
    inner = env.unwrapped
    actions = []
    step = inner._primitive_step

    def recorded(action):
        actions.append(np.asarray(action).copy())
        return step(action)

    inner._primitive_step = recorded
    return actions


@pytest.mark.parametrize(("env_id", "kwargs", "seed"), CASES)
def test_always_candidate_0__drives_as_the_nearest_frontier_explorer(env_id, kwargs, seed):
    want, _ = _frontier_episode(env_id, kwargs, seed, 400)
    env = gym.make(env_id, action_type="frontier", **kwargs)
    got = _recording(env)
    env.reset(seed=seed)
    decisions = 0
    while len(got) < 400:
        _, _, terminated, truncated, info = env.step(0)
        decisions += 1
        assert not info["fallback"]
        if terminated or truncated:
            break
    n = min(len(want), len(got))
    assert n >= 300
    assert all(np.array_equal(a, b) for a, b in zip(want[:n], got[:n], strict=True))
    assert 10 < decisions < n  # decisions are fewer than primitive steps, and more than a handful


def test_macro_steps__count_primitive_steps_and_truncate_at_the_step_limit():
    env = gym.make("OfficeExplore-v0", action_type="frontier", area_m2=600.0, max_steps=150)
    obs, _ = env.reset(seed=3)
    total, decisions = 0, 0
    while True:
        obs, _, terminated, truncated, info = env.step(0)
        total += info["primitive_steps"]
        decisions += 1
        assert info["primitive_steps"] >= 1
        assert info["steps"] == total
        assert obs["time_left"][0] == pytest.approx(1.0 - total / 150)
        if terminated or truncated:
            break
    assert truncated and not terminated
    assert total == 150 and decisions < 150


def test_coverage_auc_reward__returns_the_auc_minus_the_coverage_at_reset():
    max_steps = 120
    kwargs = {"area_m2": 600.0, "max_steps": max_steps}
    _, coverage = _frontier_episode("OfficeExplore-v0", kwargs, 3, max_steps)
    auc = np.mean(coverage + [coverage[-1]] * (max_steps + 1 - len(coverage)))
    env = gym.make(
        "OfficeExplore-v0",
        action_type="frontier",
        rewards={"new_area": 0.0, "collision": 0.0, "time": 0.0, "coverage_auc": 1.0},
        **kwargs,
    )
    _, info = env.reset(seed=3)
    assert info["coverage"] == coverage[0]
    episode_return, done = 0.0, False
    while not done:
        _, reward, terminated, truncated, info = env.step(0)
        episode_return += reward
        assert set(info["rewards"]) == {"new_area", "collision", "time", "coverage_auc"}
        done = terminated or truncated
    assert episode_return == pytest.approx(auc - coverage[0], rel=1e-9, abs=1e-12)
    assert episode_return > 0.05  # the robot did explore


def test_coverage_auc_reward__with_primitive_actions_too():
    env = gym.make(
        "RandomExplore-v0", area_m2=300.0, max_steps=60, rewards={"coverage_auc": 1.0, "time": 0.0}
    )
    env.action_space.seed(1)
    _, info = env.reset(seed=1)
    coverage, total, gains = [info["coverage"]], 0.0, 0.0
    for _ in range(60):
        _, reward, terminated, truncated, info = env.step(env.action_space.sample())
        coverage.append(info["coverage"])
        total += reward
        gains += 0.1 * info["rewards"]["new_area"] - 0.5 * info["rewards"]["collision"]
        if terminated or truncated:
            break
    auc = np.mean(coverage + [coverage[-1]] * (61 - len(coverage)))
    assert total - gains == pytest.approx(auc - coverage[0], rel=1e-9, abs=1e-12)


def test_masks__mark_the_candidates_that_exist_and_a_masked_choice_falls_back_to_0():
    kwargs = {"action_type": "frontier", "macro": {"n_candidates": 8}}
    env = gym.make("HouseExplore-v0", **kwargs)
    twin = gym.make("HouseExplore-v0", **kwargs)
    obs, _ = env.reset(seed=3)
    twin.reset(seed=3)
    # drive until fewer candidates than actions exist
    for _ in range(60):
        mask = env.unwrapped.action_masks()
        if not mask.all():
            break
        obs, *_ = env.step(0)
        twin.step(0)
    mask = env.unwrapped.action_masks()
    assert mask.shape == (8,) and mask.dtype == bool
    assert mask[0] and not mask.all()
    n = int(mask.sum())
    assert mask[:n].all() and not mask[n:].any()  # existing candidates come first
    cand = obs["candidates"].reshape(8, len(CANDIDATE_FEATURES))
    assert np.array_equal(cand[:, 0] == 1.0, mask)  # the 'valid' feature agrees
    assert not cand[n:].any()
    masked = int(np.flatnonzero(~mask)[0])
    a = env.step(masked)
    b = twin.step(0)
    assert a[4]["fallback"] and not b[4]["fallback"]
    assert a[4]["choice"] == 0
    assert all(np.array_equal(a[0][k], b[0][k]) for k in a[0])


def test_candidates__are_ranked_by_path_cost_and_describe_their_goals():
    env = gym.make("OfficeExplore-v0", action_type="frontier", area_m2=600.0)
    obs, _ = env.reset(seed=3)
    for _ in range(5):
        obs, *_ = env.step(0)
    cand = obs["candidates"].reshape(16, len(CANDIDATE_FEATURES))
    n = int(cand[:, 0].sum())
    assert n >= 2
    cost = cand[:n, CANDIDATE_FEATURES.index("path_cost")]
    dist = cand[:n, CANDIDATE_FEATURES.index("distance")]
    assert np.all(np.diff(cost) >= 0)
    assert np.all(cost >= dist - 0.015)  # a path is never shorter than the straight line
    bearing = cand[:n, 3:5]
    assert np.allclose(np.hypot(bearing[:, 0], bearing[:, 1]), 1.0, atol=1e-5)
    assert env.observation_space.contains(obs)


@pytest.mark.parametrize("action", [-1, 16, 2.0, np.nan, True, "0", None, np.array([1, 2])])
def test_bad_macro_action__is_a_one_line_action_error(action):
    env = gym.make("OfficeExplore-v0", action_type="frontier", area_m2=300.0)
    env.reset(seed=0)
    with pytest.raises(ActionError, match=r"frontier action must be (an integer )?in 0\.\.15") as error:
        env.unwrapped.step(action)
    assert "\n" not in str(error.value)


@pytest.mark.parametrize("env_id", ["OfficeExplore-v0", "SchoolSearch-v0", "RandomExplore-v0"])
def test_macro_env__passes_gymnasium_and_sb3_check_env(env_id):
    from stable_baselines3.common.env_checker import check_env as sb3_check_env

    env = make_env(env_id, action_type="frontier")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env.unwrapped)
        sb3_check_env(env.unwrapped, warn=True)


def test_macro_env__is_deterministic_for_a_seed():
    def rollout():
        env = make_env("OfficeSearch-v0", action_type="frontier", max_steps=200)
        env.action_space.seed(4)
        obs, _ = env.reset(seed=4)
        out = [obs]
        for _ in range(15):
            mask = env.unwrapped.action_masks()
            obs, reward, terminated, truncated, info = env.step(int(np.flatnonzero(mask)[-1]))
            out.append((obs, reward, info["primitive_steps"]))
            if terminated or truncated:
                break
        return out

    a, b = rollout(), rollout()
    assert len(a) == len(b)
    data_equivalence(a, b)


def test_vector_envs__native_refuses_macro_actions_sync_and_async_run_them_alike():
    with pytest.raises(ConfigError, match="vectorization_mode='async'") as error:
        gym.make_vec("OfficeExplore-v0", num_envs=2, action_type="frontier")
    assert "\n" not in str(error.value)
    runs = []
    for mode in ("sync", "async"):
        envs = gym.make_vec(
            "OfficeExplore-v0", num_envs=2, vectorization_mode=mode, action_type="frontier", area_m2=300.0
        )
        obs, _ = envs.reset(seed=0)
        masks = np.stack(envs.call("action_masks"))
        assert masks.shape == (2, 16) and masks[:, 0].all()
        steps = []
        for _ in range(3):
            obs, reward, _, _, info = envs.step(np.zeros(2, dtype=np.int64))
            steps.append((obs["candidates"].copy(), reward.copy(), info["primitive_steps"].copy()))
        assert (steps[0][2] >= 1).all()
        runs.append(steps)
        envs.close()
    for (c_sync, r_sync, p_sync), (c_async, r_async, p_async) in zip(*runs, strict=True):
        np.testing.assert_array_equal(c_sync, c_async)
        np.testing.assert_array_equal(r_sync, r_async)
        np.testing.assert_array_equal(p_sync, p_async)


def test_unknown_macro_settings__are_one_line_config_errors():
    with pytest.raises(ConfigError, match="n_candidates"):
        gym.make("OfficeExplore-v0", action_type="frontier", macro={"n_candidates": 0})
    with pytest.raises(ConfigError, match="action_type"):
        gym.make("OfficeExplore-v0", action_type="frontiers")


def test_maskable_ppo__trains_on_the_macro_env():
    sb3_contrib = pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib) is not installed")
    env = make_env("OfficeExplore-v0", action_type="frontier", max_steps=100)
    model = sb3_contrib.MaskablePPO("MultiInputPolicy", env, n_steps=16, batch_size=16, n_epochs=1, seed=0)
    model.learn(32)
    obs, _ = env.reset(seed=1)
    action, _ = model.predict(obs, action_masks=env.unwrapped.action_masks(), deterministic=True)
    assert env.unwrapped.action_masks()[int(action)]


def test_render__shows_the_candidates_and_the_goal():
    from realistic_indoor.envs.render import COLOURS

    env = gym.make("OfficeExplore-v0", action_type="frontier", area_m2=300.0, render_mode="rgb_array")
    env.reset(seed=2)
    env.step(0)

    def painted(frame, colour):
        return int(np.all(frame == np.array(colour, dtype=np.uint8), axis=-1).sum())

    frame = env.render()
    assert painted(frame, COLOURS["candidate"]) > 0
    assert painted(frame, COLOURS["goal"]) > 0
    plain = gym.make("OfficeExplore-v0", area_m2=300.0, render_mode="rgb_array")
    plain.reset(seed=2)
    assert painted(plain.render(), COLOURS["candidate"]) == 0


def test_candidate_features__room_and_unobserved_area_are_measured():
    """In an office, frontiers in rooms and on the circulation both occur, and the unobserved area
    near a frontier is positive and never exceeds the square it is measured on."""
    env = gym.make("OfficeExplore-v0", area_m2=600.0, action_type="frontier")
    obs, _ = env.reset(seed=3)
    features = []
    for _ in range(40):
        cand = obs["candidates"].reshape(16, len(CANDIDATE_FEATURES))
        features.append(cand[cand[:, 0] == 1.0])
        obs, _, terminated, truncated, _ = env.step(0)
        if terminated or truncated:
            break
    rows = np.concatenate(features)
    area = rows[:, CANDIDATE_FEATURES.index("unobserved")] * 10.0
    assert np.all(area >= 0.0) and np.all(area <= 6.1**2 + 1e-3)  # a 6.1 m square at 0.1 m cells
    assert area.max() > 5.0  # some frontier opens on unseen floor
    in_room = rows[:, CANDIDATE_FEATURES.index("in_room")]
    assert set(np.unique(in_room)) == {0.0, 1.0}  # both kinds of frontier occur


def test_waypoints__lie_on_the_grid_around_the_robot_start_heading_up():
    env = gym.make("OfficeExplore-v0", area_m2=600.0, action_type="waypoint")
    env.reset(seed=3)
    macro = env.unwrapped._macro
    assert env.action_space.n == 49
    targets = macro.targets()  # odometry frame at the start pose (0, 0, 0): x ahead, y to the left
    assert np.allclose(targets[0 * 7 + 3], [6.0, 0.0])  # row 0, middle column: 6 m ahead
    assert np.allclose(targets[3 * 7 + 0], [0.0, 6.0])  # middle row, column 0: 6 m to the left
    assert np.allclose(targets[6 * 7 + 6], [-6.0, -6.0])  # behind and to the right
    mask = env.unwrapped.action_masks()
    assert not mask[3 * 7 + 3]  # the robot's own cell is no goal


def test_waypoints__snap_to_reachable_known_floor_and_drive_there():
    from realistic_indoor.sim.mapping import MAPPED_FREE

    env = gym.make("OfficeExplore-v0", area_m2=600.0, action_type="waypoint")
    obs, _ = env.reset(seed=3)
    macro = env.unwrapped._macro
    own = macro.navigator.map
    offered = macro.candidates.xy
    for x, y in offered:
        assert own.state[own.to_cell(x, y)] == MAPPED_FREE
    ahead = 2 * 7 + 3  # 2 m ahead of the robot, on the floor it sees through the entrance
    assert np.hypot(*(offered[ahead] - macro.targets()[ahead])) <= 0.1 * np.sqrt(2) / 2 + 1e-9
    x0 = float(obs["pose"][0])
    obs, _, _, _, info = env.step(ahead)
    assert not info["fallback"]
    assert float(obs["pose"][0]) > x0 + 1.0  # it drove ahead


def test_waypoint_env__passes_check_env():
    from stable_baselines3.common.env_checker import check_env as sb3_check_env

    env = make_env("HouseSearch-v0", action_type="waypoint")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env.unwrapped)
        sb3_check_env(env.unwrapped, warn=True)
    with pytest.raises(ConfigError, match="odd"):
        gym.make("HouseExplore-v0", action_type="waypoint", macro={"waypoint_grid": 4})
    with pytest.raises(ActionError, match=r"waypoint action must be in 0\.\.48"):
        env.unwrapped.step(49)
