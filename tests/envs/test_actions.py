"""Actions are checked: non-finite, wrongly shaped or out-of-range actions raise ActionError."""

from __future__ import annotations

import math

import gymnasium as gym
import numpy as np
import pytest

import realistic_indoor.envs  # noqa: F401  (registers the ids)
from realistic_indoor.envs import ExploreEnv, preset_config
from realistic_indoor.envs.actions import ActionMap
from realistic_indoor.errors import ActionError, ConfigError, RealisticIndoorError
from realistic_indoor.sim.victims import VictimConfig

V_MAX, W_MAX = 0.5, 2.0  # m/s, rad/s


@pytest.fixture
def continuous() -> ActionMap:
    return ActionMap("continuous", V_MAX, W_MAX)


@pytest.fixture
def discrete() -> ActionMap:
    return ActionMap("discrete", V_MAX, W_MAX)


# -- continuous ------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("action", "command"),
    [
        (np.array([1.0, 0.0], np.float32), (0.5, 0.0)),
        (np.array([-0.5, 0.25]), (-0.25, 0.5)),
        ([0.0, -1.0], (0.0, -2.0)),
        ((1, 1), (0.5, 2.0)),  # integers are numbers too
        (np.array([3.0, -7.5], np.float32), (0.5, -2.0)),  # finite values outside [-1, 1]: clipped
        ([-1e30, 1e30], (-0.5, 2.0)),
    ],
)
def test_continuous__scales_and_clips_finite_actions(continuous, action, command):
    assert continuous.command(action) == pytest.approx(command)


@pytest.mark.parametrize(
    "action",
    [
        np.array([np.nan, 0.0], np.float32),
        np.array([0.0, np.nan]),
        [math.inf, 0.0],
        (0.5, -math.inf),
    ],
)
def test_continuous__refuses_nan_and_infinities(continuous, action):
    with pytest.raises(ActionError, match=r"finite numbers \(linear, turn\) in \[-1, 1\]") as error:
        continuous.command(action)
    assert "nan" in str(error.value) or "inf" in str(error.value)  # it shows the action given
    assert "clipped" in str(error.value)  # and says what is allowed


@pytest.mark.parametrize(
    ("action", "given"),
    [
        (np.zeros(3, np.float32), "shape (3,)"),
        (np.zeros((1, 2), np.float32), "shape (1, 2)"),
        ([[0.1], [0.2]], "shape (2, 1)"),
        ([0.5], "shape (1,)"),
        (0.5, "got 0.5"),
        (None, "got None"),
    ],
)
def test_continuous__wrong_shape_names_the_expected_and_the_given_shape(continuous, action, given):
    with pytest.raises(ActionError, match=r"shape \(2,\)") as error:
        continuous.command(action)
    assert given in str(error.value)


def test_continuous__non_numbers_are_refused(continuous):
    with pytest.raises(ActionError, match="2 numbers"):
        continuous.command(["fast", "left"])


# -- discrete --------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("action", "command"),
    [
        (0, (0.5, 0.0)),  # forward
        (3, (0.0, 2.0)),  # turn left
        (5, (-0.25, 0.0)),  # back at half speed
        (np.int64(1), (0.25, 1.0)),  # forward-left
        (np.uint8(2), (0.25, -1.0)),  # forward-right
        (np.array(4, dtype=np.int32), (0.0, -2.0)),  # a 0-d integer array: turn right
    ],
)
def test_discrete__integers_in_range_select_the_table_row(discrete, action, command):
    assert discrete.command(action) == pytest.approx(command)


@pytest.mark.parametrize("action", [-1, 6, np.int64(-1), np.array(6)])
def test_discrete__out_of_range_names_the_valid_range(discrete, action):
    with pytest.raises(ActionError, match=r"in 0\.\.5 .*got -?\d"):
        discrete.command(action)


@pytest.mark.parametrize(
    ("action", "kind"),
    [
        (2.9, "float"),
        (2.0, "float"),
        (True, "bool"),
        (np.bool_(False), "bool"),
        (np.array(2.0), "ndarray"),
        (np.array([2]), "ndarray"),  # one integer in a 1-d array: not a scalar
        ("2", "str"),
    ],
)
def test_discrete__non_integers_are_refused_not_rounded(discrete, action, kind):
    with pytest.raises(ActionError, match=rf"an integer in 0\.\.5 .* of type {kind}"):
        discrete.command(action)


# -- batches (the native vector env's step) ---------------------------------------------------------
def test_batch__discrete_rows_are_the_single_commands(discrete):
    # forward, forward-left, forward-right, turn left, turn right, back at half speed
    expected = [(0.5, 0.0), (0.25, 1.0), (0.25, -1.0), (0.0, 2.0), (0.0, -2.0), (-0.25, 0.0)]
    batch = discrete.commands(np.array([5, 0, 3, 1, 4, 2]), 6)
    np.testing.assert_allclose(batch, [expected[k] for k in (5, 0, 3, 1, 4, 2)])
    np.testing.assert_allclose([discrete.command(k) for k in range(6)], expected)


def test_batch__continuous_actions_are_scaled_and_clipped(continuous):
    batch = continuous.commands(np.array([[1.0, 0.0], [3.0, -7.5], [-0.5, 0.25]]), 3)
    np.testing.assert_allclose(batch, [(0.5, 0.0), (0.5, -2.0), (-0.25, 0.5)])


@pytest.mark.parametrize(
    ("kind", "actions"),
    [
        ("discrete", np.array([0, 6])),
        ("discrete", np.array([0.0, 1.0])),
        ("discrete", np.array([0, 1, 2])),
        ("continuous", np.array([[0.0, np.nan], [0.0, 0.0]])),
        ("continuous", np.zeros((3, 2))),
    ],
)
def test_batch__an_action_outside_the_space_is_one_action_error(kind, actions):
    with pytest.raises(ActionError, match="actions must be"):
        ActionMap(kind, V_MAX, W_MAX).commands(actions, 2)


def test_action_error__is_a_value_error_of_the_package():
    assert issubclass(ActionError, RealisticIndoorError) and issubclass(ActionError, ValueError)


# -- through the environment -----------------------------------------------------------------------
def test_env_step__refuses_a_bad_action_before_moving(toy_building):
    env = ExploreEnv(building=toy_building)
    env.reset(seed=0)
    pose = env.simulation.robot.pose
    with pytest.raises(ActionError, match="finite"):
        env.step(np.array([np.nan, 0.0], np.float32))
    with pytest.raises(ActionError, match=r"shape \(2,\).*shape \(3,\)"):
        env.step(np.zeros(3, np.float32))
    assert env.simulation.robot.pose == pose and env.simulation.path_length_m == 0.0
    _, _, _, truncated, _ = env.step(np.array([1.0, 0.0], np.float32))  # still usable
    assert env.simulation.path_length_m > 0.0 and not truncated


def test_env_step__clips_like_a_full_action(toy_building):
    a = ExploreEnv(building=toy_building)
    b = ExploreEnv(building=toy_building)
    a.reset(seed=0)
    b.reset(seed=0)
    for _ in range(5):
        a.step(np.array([9.0, -4.0], np.float32))
        b.step(np.array([1.0, -1.0], np.float32))
    assert a.simulation.robot.pose == b.simulation.robot.pose


@pytest.mark.parametrize("action", [-1, 6, 2.9])
def test_discrete_env_step__refuses_bad_actions(toy_building, action):
    env = gym.make("OfficeExplore-v0", building=toy_building, action_type="discrete")
    env.reset(seed=0)
    with pytest.raises(ActionError, match=r"0\.\.5"):
        env.step(action)


def test_discrete_env_step__takes_numpy_integers(toy_building):
    env = gym.make("OfficeExplore-v0", building=toy_building, action_type="discrete")
    env.reset(seed=0)
    for action in (np.int64(0), np.array(0, dtype=np.int8), 0):
        env.step(action)
    assert env.unwrapped.simulation.path_length_m > 0.0


# -- keywords a task does not use ------------------------------------------------------------------
@pytest.mark.parametrize("victims", [{"n_victims": 2}, VictimConfig()])
def test_victims_on_an_explore_id__is_an_error(victims):
    with pytest.raises(ConfigError, match="'victims' applies to search environments only") as error:
        gym.make("OfficeExplore-v0", victims=victims)
    assert "\n" not in str(error.value)


def test_coverage_target_on_a_search_id__is_an_error():
    with pytest.raises(ConfigError, match="'coverage_target' applies to explore environments only"):
        gym.make("HouseSearch-v0", coverage_target=0.5)


def test_search_config_given_to_an_explore_env__is_an_error(toy_building):
    config = preset_config("OfficeSearch-v0", victims={"n_victims": 5}, building=toy_building)
    with pytest.raises(ConfigError, match="'victims'"):
        ExploreEnv(config)


def test_preset_config__refuses_the_fields_of_the_other_task():
    with pytest.raises(ConfigError, match="'victims'"):
        preset_config("SchoolExplore-v0", victims={"n_victims": 1})
    assert preset_config("SchoolSearch-v0", victims={"n_victims": 1}).victims.n_victims == 1


def test_each_task_keeps_its_own_fields(toy_building):
    search = gym.make("OfficeSearch-v0", building=toy_building, victims={"n_victims": 2})
    explore = gym.make("OfficeExplore-v0", building=toy_building, coverage_target=0.5)
    assert search.unwrapped.config.victims.n_victims == 2
    assert explore.unwrapped.config.coverage_target == 0.5


def test_unknown_keyword__is_an_error():
    with pytest.raises(ConfigError, match="no field 'victim_count'"):
        gym.make("OfficeSearch-v0", victim_count=2)
