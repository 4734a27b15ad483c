"""The native vector environment: Gymnasium's vector contract, seeds, autoreset, same episodes."""

from __future__ import annotations

import copy
import pickle

import gymnasium as gym
import numpy as np
import pytest
from env_helpers import TEST_AREAS_M2
from gymnasium.utils.env_checker import data_equivalence
from gymnasium.vector import AutoresetMode

from realistic_indoor.envs import PRESETS
from realistic_indoor.envs.vector import INFO_KEYS, BatchedExploreEnv
from realistic_indoor.envs.vector_search import BatchedSearchEnv
from realistic_indoor.errors import ActionError, ConfigError

VECTOR_IDS = sorted(k for k, p in PRESETS.items() if p.vector_entry_point)
POSE_TOLERANCE_M = 0.05
"""The compiled physics' tolerance against pymunk (tests/sim/test_disc_physics.py)."""


def _make(env_id: str = "OfficeExplore-v0", n: int = 3, **kwargs) -> BatchedExploreEnv:
    area = TEST_AREAS_M2[PRESETS[env_id].building_type]
    return gym.make_vec(env_id, num_envs=n, area_m2=area, **kwargs)


def _rollout(envs, seed: int, n_steps: int) -> list:
    envs.action_space.seed(seed)
    out = [envs.reset(seed=seed)]
    for _ in range(n_steps):
        out.append(envs.step(envs.action_space.sample()))
    return out


def test_every_registered_id_has_a_native_vector_env():
    assert sorted(PRESETS) == VECTOR_IDS


@pytest.mark.parametrize("env_id", VECTOR_IDS)
def test_make_vec__returns_the_native_vector_env_with_batched_spaces(env_id):
    envs = _make(env_id)
    assert isinstance(envs, BatchedExploreEnv)
    assert envs.metadata["autoreset_mode"] == AutoresetMode.NEXT_STEP
    assert envs.config.max_steps == PRESETS[env_id].max_episode_steps
    obs, info = envs.reset(seed=0)
    assert envs.observation_space.contains(obs)
    for _ in range(5):
        obs, reward, terminated, truncated, info = envs.step(envs.action_space.sample())
        assert envs.observation_space.contains(obs)
    assert reward.shape == terminated.shape == truncated.shape == (3,)
    assert terminated.dtype == truncated.dtype == np.bool_
    for key in INFO_KEYS:
        assert info[key].shape == (3,) and info[f"_{key}"].all()
    search = env_id.endswith("Search-v0")
    assert set(info["rewards"]) == {"new_area", "collision", "time"} | ({"victim"} if search else set())
    if search:
        assert isinstance(envs, BatchedSearchEnv) and obs["victims"].shape == (3, 9)
        assert (info["victims_total"] == 3).all()
    envs.close()


def test_vector_env__same_seed_gives_the_same_rollout_and_sub_envs_differ():
    a, b = _rollout(_make(), 7, 20), _rollout(_make(), 7, 20)
    assert data_equivalence(a, b, exact=True)
    scans = a[-1][0]["scan"]
    assert not np.array_equal(scans[0], scans[1])


@pytest.mark.parametrize(
    ("env_id", "extra"),
    [
        ("OfficeExplore-v0", {}),
        # many victims and a longer-range sensor: two are found during the steps compared
        ("HouseSearch-v0", {"victims": {"n_victims": 10, "sensor_range_m": 6.0}}),
    ],
)
def test_vector_env__sub_env_k_is_the_single_env_seeded_with_seed_plus_k(env_id, extra):
    area = TEST_AREAS_M2[PRESETS[env_id].building_type]
    envs = gym.make_vec(env_id, num_envs=2, area_m2=area, **extra)
    obs, _ = envs.reset(seed=12)
    single = gym.make(env_id, area_m2=area, **extra)
    first, _ = single.reset(seed=13)
    assert data_equivalence(first, {k: v[1] for k, v in obs.items()}, exact=True)
    rng = np.random.default_rng(0)
    found = 0
    for _ in range(150):  # one physics, one set of kernels: the same episode, exactly
        actions = rng.uniform(-1, 1, (2, 2)).astype(np.float32)
        obs, reward, terminated, truncated, info = envs.step(actions)
        one, one_reward, one_terminated, one_truncated, one_info = single.step(actions[1])
        assert data_equivalence(one, {k: v[1] for k, v in obs.items()}, exact=True)
        assert (one_reward, one_terminated, one_truncated) == (reward[1], terminated[1], truncated[1])
        assert one_info["coverage"] == info["coverage"][1]
        assert one_info["path_length_m"] == pytest.approx(info["path_length_m"][1], abs=1e-9)
        assert one_info["rewards"] == {k: v[1] for k, v in info["rewards"].items()}
        if "victims_found" in one_info:
            assert one_info["victims_found"] == info["victims_found"][1]
            found = one_info["victims_found"]
        if one_terminated or one_truncated:
            break
    assert found > 0 or "Search" not in env_id


def test_vector_env__follows_the_pymunk_reference_within_the_physics_tolerance():
    envs = _make(n=1)
    obs, _ = envs.reset(seed=3)
    single = gym.make("OfficeExplore-v0", area_m2=TEST_AREAS_M2["office"], robot={"physics": "pymunk"})
    single.reset(seed=3)
    rng = np.random.default_rng(1)
    exact_steps = 0
    for _ in range(150):
        actions = rng.uniform(-1, 1, (1, 2)).astype(np.float32)
        obs, *_ = envs.step(actions)
        one, *_ = single.step(actions[0])
        assert np.abs(one["pose"][:2] - obs["pose"][0, :2]).max() < POSE_TOLERANCE_M
        exact_steps += bool(np.array_equal(one["scan"], obs["scan"][0]))
    assert exact_steps > 0


def test_vector_env__refuses_the_pymunk_physics():
    with pytest.raises(ConfigError, match="compiled"):
        _make(robot={"physics": "pymunk"})


def test_vector_env__autoresets_on_the_next_step():
    envs = _make(n=2, max_steps=4)
    envs.reset(seed=0)
    actions = np.zeros((2, 2), np.float32)
    for _ in range(3):
        _, _, terminated, truncated, _ = envs.step(actions)
        assert not (terminated | truncated).any()
    _, _, _, truncated, info = envs.step(actions)
    assert truncated.all() and info["path_length_m"].shape == (2,)
    obs, reward, terminated, truncated, info = envs.step(actions)  # the reset step
    assert (reward == 0).all() and not (terminated | truncated).any()
    assert (info["path_length_m"] == 0).all()
    assert np.allclose(obs["pose"], 0.0)


def test_vector_env__a_fixed_building_keeps_its_world(toy_building):
    envs = gym.make_vec("OfficeExplore-v0", num_envs=2, building=toy_building, max_steps=3)
    envs.reset(seed=0)
    worlds = list(envs.unwrapped._batch.worlds)
    for _ in range(5):
        envs.step(np.zeros((2, 2), np.float32))
    assert envs.unwrapped._batch.worlds == worlds


def test_vector_env__refuses_bad_actions_and_arguments():
    envs = _make(n=2)
    with pytest.raises(gym.error.ResetNeeded):
        envs.step(np.zeros((2, 2), np.float32))
    envs.reset(seed=0)
    for bad in (np.zeros((3, 2)), np.full((2, 2), np.nan), np.zeros(2)):
        with pytest.raises(ActionError):
            envs.step(bad)
    with pytest.raises(ConfigError):
        BatchedExploreEnv(num_envs=0)
    with pytest.raises(ConfigError):
        BatchedExploreEnv(num_envs=2, victims={"n_victims": 2})
    with pytest.raises(ConfigError):
        envs.reset(seed=[1, 2, 3])


def test_vector_env__discrete_actions():
    envs = _make(n=2, action_type="discrete")
    envs.reset(seed=0)
    obs, *_ = envs.step(np.array([0, 3]))
    assert envs.observation_space.contains(obs)
    with pytest.raises(ActionError):
        envs.step(np.array([0, 6]))


def test_vector_env__works_with_gymnasium_vector_wrappers():
    envs = gym.wrappers.vector.RecordEpisodeStatistics(_make(n=2, max_steps=3))
    envs.reset(seed=0)
    for _ in range(3):
        *_, info = envs.step(envs.action_space.sample())
    assert info["_episode"].all() and (info["episode"]["l"] == 3).all()


def test_vector_env__many_robots_step_on_numba_threads_and_match_the_single_env():
    n = 32  # from 32 robots on, the step runs on numba's threads (when there are two or more)
    envs = _make(n=n)
    envs.reset(seed=40)
    single = gym.make("OfficeExplore-v0", area_m2=TEST_AREAS_M2["office"])
    single.reset(seed=40 + n - 1)
    rng = np.random.default_rng(2)
    for _ in range(5):
        actions = rng.uniform(-1, 1, (n, 2)).astype(np.float32)
        obs, reward, *_ = envs.step(actions)
        one, one_reward, *_ = single.step(actions[-1])
        assert data_equivalence(one, {k: v[-1] for k, v in obs.items()}, exact=True)
        assert one_reward == reward[-1]


def test_vector_env__first_scans_match_the_single_env_also_along_cell_boundaries():
    # Start poses sit on round coordinates facing along an axis, so some beams run exactly along
    # a cell boundary: a last-bit difference in the ray's start put it in the next row (2 of
    # these 40 offices did before the batch used the single robot's arithmetic).
    n = 40
    envs = gym.make_vec("OfficeExplore-v0", num_envs=n, area_m2=600.0)
    obs, _ = envs.reset(seed=0)
    single = gym.make("OfficeExplore-v0", area_m2=600.0)
    for k in range(n):
        first, _ = single.reset(seed=k)
        assert data_equivalence(first, {key: v[k] for key, v in obs.items()}, exact=True), k


def test_vector_env__an_episode_ending_both_ways_at_once_reports_both_flags_as_the_single_env():
    kwargs = {"area_m2": TEST_AREAS_M2["office"], "max_steps": 1, "coverage_target": 0.001}
    envs = gym.make_vec("OfficeExplore-v0", num_envs=1, **kwargs)
    envs.reset(seed=5)
    single = gym.make("OfficeExplore-v0", **kwargs)
    single.reset(seed=5)
    action = np.zeros((1, 2), np.float32)
    _, _, terminated, truncated, _ = envs.step(action)
    _, _, one_terminated, one_truncated, _ = single.step(action[0])
    assert (one_terminated, one_truncated) == (True, True)  # the goal, on the last allowed step
    assert (terminated[0], truncated[0]) == (one_terminated, one_truncated)


def test_vector_env__refuses_bad_restarts_seeds_and_use_after_close():
    envs = _make(n=2)
    with pytest.raises(gym.error.ResetNeeded):
        envs.restart(np.array([0]))
    envs.reset(seed=0)
    for bad in ([2], [-1], [0.5]):
        with pytest.raises(ConfigError, match=r"0\.\.1"):
            envs.restart(np.array(bad))
    for seed in (-5, [0, -1], [0, "a"]):
        with pytest.raises(ConfigError, match="seed"):
            envs.reset(seed=seed)
    envs.close()
    with pytest.raises(gym.error.ResetNeeded):
        envs.step(np.zeros((2, 2), np.float32))
    assert gym.make_vec("OfficeExplore-v0", num_envs=np.int64(2), area_m2=300.0).num_envs == 2


def test_vector_env__reset_mask_starts_only_the_masked_sub_envs_as_the_single_env_would():
    envs, twin = _make(n=3), _make(n=3)  # the twin never resets: sub-envs 0 and 2 must follow it
    envs.reset(seed=0)
    twin.reset(seed=0)
    actions = np.tile(np.array([1.0, 0.2], np.float32), (3, 1))
    for _ in range(4):
        before, *_ = envs.step(actions)
        twin.step(actions)
    obs, info = envs.reset(seed=10, options={"reset_mask": np.array([False, True, False])})
    single = gym.make("OfficeExplore-v0", area_m2=TEST_AREAS_M2["office"])
    first, _ = single.reset(seed=11)  # sub-env 1 seeded with 10 + 1
    assert data_equivalence(first, {k: v[1] for k, v in obs.items()}, exact=True)
    assert info["path_length_m"][1] == 0.0 and info["path_length_m"][0] > 0.0
    assert info["_coverage"].tolist() == [False, True, False]  # as Gymnasium's: what was reset
    for k in (0, 2):  # the others keep their state and last observation
        assert data_equivalence(
            {n: v[k] for n, v in before.items()}, {n: v[k] for n, v in obs.items()}, exact=True
        )
    for _ in range(3):
        obs, *_ = envs.step(actions)
        one, *_ = single.step(actions[1])
        other, *_ = twin.step(actions)
        assert data_equivalence(one, {k: v[1] for k, v in obs.items()}, exact=True)
        for k in (0, 2):  # same noise: their generators were not reseeded
            assert data_equivalence(
                {n: v[k] for n, v in other.items()}, {n: v[k] for n, v in obs.items()}, exact=True
            )


def test_vector_env__the_largest_step_limit_never_truncates_and_one_beyond_int64_is_refused():
    from realistic_indoor.envs.config import MAX_STEPS

    envs = _make(n=2, max_steps=MAX_STEPS)
    envs.reset(seed=0)
    _, _, _, truncated, _ = envs.step(np.zeros((2, 2), np.float32))
    assert not truncated.any()
    with pytest.raises(ConfigError, match=r"EnvConfig.max_steps must be an integer in \[1, 1000000\]"):
        _make(n=2, max_steps=2**70)


def test_vector_env__refuses_bad_reset_options():
    envs = _make(n=2)
    with pytest.raises(gym.error.ResetNeeded, match="reset_mask"):
        envs.reset(options={"reset_mask": np.array([True, False])})
    envs.reset(seed=0)
    for bad in ([True, False], np.array([1, 0]), np.array([True]), np.array([False, False])):
        with pytest.raises(ConfigError, match="reset_mask"):
            envs.reset(options={"reset_mask": bad})
    with pytest.raises(ConfigError, match="unknown reset option 'victims'"):
        envs.reset(options={"victims": [[1.0, 1.0]]})
    with pytest.raises(ConfigError, match="must be a Building"):
        envs.reset(options={"building": "office.json"})
    drawn = gym.make_vec("OfficeExplore-v0", num_envs=2, generator=lambda rng: "office.json")
    with pytest.raises(ConfigError, match="must be a Building, got str"):  # as the single env's
        drawn.reset(seed=0)
    search = _make("OfficeSearch-v0", n=2)
    search.reset(seed=0)
    before = search.unwrapped.victims
    with pytest.raises(ConfigError, match="victims must be 3 finite"):
        search.reset(options={"victims": [[1.0, 2.0]]})
    for (xy, found), (xy0, found0) in zip(search.unwrapped.victims, before, strict=True):  # nothing reset
        assert np.array_equal(xy, xy0) and np.array_equal(found, found0)


@pytest.mark.parametrize("env_id", ["OfficeExplore-v0", "OfficeSearch-v0"])
def test_vector_env__reset_options_give_every_started_sub_env_the_single_envs_episode(env_id, toy_building):
    options = {"building": toy_building}
    if "Search" in env_id:
        options["victims"] = [[2.0, 2.0], [5.0, 3.0], [8.0, 6.0]]
    envs = gym.make_vec(env_id, num_envs=2)
    obs, info = envs.reset(seed=30, options=options)
    assert envs.unwrapped.buildings == [toy_building, toy_building]
    assert envs.unwrapped._batch.worlds[0] is envs.unwrapped._batch.worlds[1]  # built once
    actions = np.random.default_rng(3).uniform(-1, 1, (40, 2, 2)).astype(np.float32)
    for k in range(2):
        single = gym.make(env_id)
        one, one_info = single.reset(seed=30 + k, options=options)
        assert data_equivalence(one, {n: v[k] for n, v in obs.items()}, exact=True)
        assert tuple(info["start_pose"][k]) == one_info["start_pose"] and info["_start_pose"][k]
        twin = gym.make_vec(env_id, num_envs=2)
        twin.reset(seed=30, options=options)
        for a in actions:
            one, *_ = single.step(a[k])
            got, *_ = twin.step(a)
            assert data_equivalence(one, {n: v[k] for n, v in got.items()}, exact=True)


@pytest.mark.parametrize("env_id", ["OfficeExplore-v0", "HouseSearch-v0"])
def test_vector_env__a_pickled_or_deep_copied_env_goes_on_as_the_original(env_id):
    envs = _make(env_id, n=2, max_steps=20)
    envs.reset(seed=4)
    actions = np.random.default_rng(2).uniform(-1, 1, (60, 2, 2)).astype(np.float32)
    for a in actions[:7]:
        envs.step(a)
    copies = [pickle.loads(pickle.dumps(envs)), copy.deepcopy(envs)]
    batch = copies[0].unwrapped._batch
    assert batch.skips[0] is batch.worlds[0].raycaster._skip  # one skip field per world, read-only
    assert not batch.skips[0].flags.writeable
    for a in actions[7:]:  # two autoresets each: the buildings drawn from the copied generators
        out = envs.step(a)
        for twin in copies:
            assert data_equivalence(out, twin.step(a), exact=True)


def _hand_made(*rooms, doors=()):
    from realistic_indoor.building import Building

    return Building("office", tuple(rooms), tuple(doors), {"generator": "hand"})


def test_vector_env__a_refused_reset_changes_nothing():
    from realistic_indoor.building import Door, Room

    corridor = _hand_made(
        Room.rectangle("c", "corridor", "corridor", (0, 0, 10, 2)),
        doors=(Door("entrance", "c", None, 0.0, 1.0, 1.2, np.pi / 2),),
    )
    envs, twin = _make("OfficeSearch-v0", n=3), _make("OfficeSearch-v0", n=3)
    actions = np.random.default_rng(5).uniform(-1, 1, (30, 3, 2)).astype(np.float32)
    for e in (envs, twin):
        e.reset(seed=0)
        e.step(actions[0])
    with pytest.raises(ConfigError, match="no room can hold victims"):  # a corridor only
        envs.reset(seed=7, options={"building": corridor})
    with pytest.raises(ConfigError, match="victims must be 3 finite"):
        envs.reset(seed=7, options={"victims": [[1.0, 2.0]]})
    for a in actions[1:]:  # the same state, the same generators
        assert data_equivalence(envs.step(a), twin.step(a), exact=True)


def test_vector_env__after_a_refused_first_reset_a_step_asks_for_a_reset():
    from realistic_indoor.building import Room

    tiny = _hand_made(Room.rectangle("r", "small", "office", (0, 0, 0.6, 0.6)))  # no room for the robot
    envs = _make(n=2)
    with pytest.raises(ConfigError):
        envs.reset(seed=0, options={"building": tiny})
    with pytest.raises(gym.error.ResetNeeded):
        envs.step(np.zeros((2, 2), np.float32))
    envs.reset(seed=0)
    envs.step(np.zeros((2, 2), np.float32))


def test_vector_env__sub_envs_in_one_building_count_its_world_once(toy_building):
    one = gym.make_vec("OfficeExplore-v0", num_envs=1, building=toy_building)
    two = gym.make_vec("OfficeExplore-v0", num_envs=2, building=toy_building)
    one.reset(seed=0)
    two.reset(seed=0)
    world = one.unwrapped._batch.worlds[0].nbytes
    assert two.unwrapped.nbytes - one.unwrapped.nbytes == one.unwrapped.nbytes - world  # a robot's share


def test_vector_env__an_autoreset_whose_building_fails_changes_no_sub_env(toy_building):
    calls = []

    def flaky(rng):  # the fourth building asked for (the first autoreset's second) fails
        calls.append(1)
        if len(calls) == 4:
            raise ConfigError("no building this time")
        rng.random()
        return toy_building

    envs = gym.make_vec("OfficeExplore-v0", num_envs=2, generator=flaky, max_steps=2)
    envs.reset(seed=0)
    zero = np.zeros((2, 2), np.float32)
    envs.step(zero)
    envs.step(zero)  # both episodes end
    steps = envs.unwrapped._steps.copy()
    with pytest.raises(ConfigError, match="no building this time"):
        envs.step(zero)
    assert np.array_equal(envs.unwrapped._steps, steps)  # sub-env 0 was not reset alone
    obs, reward, *_ = envs.step(zero)  # the next step starts both
    assert (reward == 0).all() and np.allclose(obs["pose"], 0.0)


@pytest.mark.parametrize(
    ("kwargs", "said"),
    [
        ({"robot": {"physics": "pymunk"}}, "robot physics 'pymunk' (only the compiled physics runs batched); use gym.make_vec(..., vectorization_mode='sync')"),
        ({"action_type": "frontier"}, "action_type 'frontier' (only primitive actions, continuous or discrete, run batched); use gym.make_vec(..., vectorization_mode='async' (one process per copy))"),
        ({"extra_observations": ("global_map",)}, "the extra observations ['global_map']; use gym.make_vec(..., vectorization_mode='sync')"),
        ({"rewards": {"coverage_auc": 1.0}}, "the coverage_auc reward term; use gym.make_vec(..., vectorization_mode='sync')"),
    ],
)  # fmt: skip
def test_vector_env__what_it_cannot_run_is_a_one_line_error_naming_the_vectorization_that_can(kwargs, said):
    with pytest.raises(ConfigError) as error:
        gym.make_vec("OfficeExplore-v0", num_envs=2, **kwargs)
    assert str(error.value) == f"the native vector env cannot run {said}"
