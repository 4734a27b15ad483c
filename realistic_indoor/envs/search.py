"""Victim search: explore a building until the victim sensor has seen every victim."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from gymnasium import spaces

from realistic_indoor.envs.explore import ExploreEnv
from realistic_indoor.envs.observations import explore_observations
from realistic_indoor.envs.simulation import Simulation
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.victims import Victims, relative_polar

if TYPE_CHECKING:
    from realistic_indoor.envs.config import EnvConfig

__all__ = ["SearchEnv", "VictimObservation"]


class VictimObservation:
    """What the victim sensor sees: ``(3 * n_victims,)`` float32, nearest victim first.

    Entries ``3i`` to ``3i + 2`` describe the ``i``-th nearest victim in view: ``(1, range /
    sensor_range_m, bearing / pi)``, bearing 0 straight ahead and positive to the left;
    entries beyond the victims in view are zeros. (Flat, as stable-baselines3's
    ``MultiInputPolicy`` wants vectors.) The victims in view are those the simulation's victim
    sensor saw at the latest step (or reset).
    """

    def __init__(self, config: EnvConfig) -> None:
        c = config.victims
        self._scale = np.array([1.0 / c.sensor_range_m, 1.0 / np.pi])
        low = np.tile(np.array([0.0, 0.0, -1.0], np.float32), c.n_victims)
        self.space = spaces.Box(low, np.ones_like(low), (3 * c.n_victims,), np.float32)

    def observe(self, sim: Simulation) -> np.ndarray:
        """The victims in view (a new array)."""
        return self.encode(sim.robot.pose, _victims_of(sim))

    def encode(self, pose: tuple[float, float, float], victims: Victims) -> np.ndarray:
        """The observation of ``victims`` (their latest look) from ``pose`` (m, m, rad); a new array."""
        out = np.zeros((len(victims.xy), 3), dtype=np.float32)
        seen = victims.in_view
        if seen.any():
            ranges, bearings = relative_polar(pose, victims.xy[seen])
            order = np.argsort(ranges, kind="stable")
            rows = np.stack([ranges[order], bearings[order]], axis=1) * self._scale
            out[: len(order), 0] = 1.0
            out[: len(order), 1:] = np.clip(rows, (0.0, -1.0), (1.0, 1.0))
        return out.ravel()


class SearchEnv(ExploreEnv):
    """Search a building for victims with a laser-equipped robot and a victim sensor.

    ## Description

    The exploration task of :class:`~realistic_indoor.envs.explore.ExploreEnv`, with
    ``victims.n_victims`` victims (3 by default) placed at random in the rooms of the building
    (not in corridors or halls by default, at least 0.3 m from walls). A victim is found the
    first time the victim sensor sees it: within ``victims.sensor_range_m`` (3 m), within
    ``victims.sensor_fov_rad`` (120 degrees) of the heading, and in line of sight. The goal
    is to find every victim as fast as possible.

    The simulation (:class:`~realistic_indoor.envs.simulation.Simulation`) places the victims
    and senses them in every step, after the scan; the environment only reads what the step
    reports (the ``victim`` reward), the found flags (termination, ``info``) and the victims
    in view (the observation). A subclass with other rewards finds the same victims.

    ## Action Space

    As :class:`~realistic_indoor.envs.explore.ExploreEnv`: ``Box(-1, 1, (2,))`` scaled to
    ``(v m/s, w rad/s)``, or ``Discrete(6)`` with ``action_type="discrete"``.

    ## Observation Space

    A ``Dict`` with the keys of the exploration environment (`scan`, `local_map`, `velocity`,
    `pose`) and:

    | Key       | Shape            | Dtype   | Min          | Max       | Meaning                                   |
    |-----------|------------------|---------|--------------|-----------|-------------------------------------------|
    | `victims` | `(3 n_victims,)` | float32 | (0, 0, -1, ...) | (1, 1, 1, ...) | victims in view, nearest first, three numbers each: 1, range / sensor range, bearing / pi (0 ahead, > 0 left); zeros for none |

    ## Rewards

    The exploration terms (`new_area` in m2, `collision`, `time`) plus:

    | Term     | Value                          | Default weight |
    |----------|--------------------------------|----------------|
    | `victim` | victims found in this step     | 5.0            |

    ## Starting State

    As in exploration (``info["start_pose"]`` after ``reset``): at rest inside the entrance (or
    in the largest hall of a plan without one). Victims in view from the start count as found,
    without reward.

    ## Episode End

    1. Termination: every victim has been found.
    2. Truncation: ``max_steps`` control steps have passed.

    ## Arguments

    Those of :class:`~realistic_indoor.envs.explore.ExploreEnv` (every
    :class:`~realistic_indoor.envs.config.EnvConfig` field), of which ``victims``
    (:class:`~realistic_indoor.sim.victims.VictimConfig`: number, allowed rooms, clearance,
    sensor range and field of view) is used by search only; ``coverage_target`` (exploration
    only) is refused with a :class:`~realistic_indoor.errors.ConfigError`.
    ``info`` adds ``victims_found`` and ``victims_total``. ``reset(options={"victims": xy})``
    puts the episode's victims at the ``(n_victims, 2)`` positions ``xy`` (m) instead of
    drawing them (with ``"building"``, a fixed scenario).

    ```python
    >>> import gymnasium as gym
    >>> import realistic_indoor.envs
    >>> env = gym.make("OfficeSearch-v0", area_m2=400.0, victims={"n_victims": 2})
    >>> obs, info = env.reset(seed=0)
    >>> obs["victims"].shape, info["victims_total"]
    ((6,), 2)

    ```

    ## Version History

    * v0: Initial version.
    """

    reset_options = frozenset({"building", "victims"})
    task = "search"

    @property
    def victims(self) -> tuple[np.ndarray, np.ndarray]:
        """``(positions (N, 2) m, found (N,) bool)`` of this episode's victims (copies)."""
        victims = _victims_of(self._sim)
        return victims.xy.copy(), victims.found.copy()

    def _make_simulation(self) -> Simulation:
        return Simulation(self.config, victims=True)

    def _make_observations(self) -> dict[str, Any]:
        return {**explore_observations(self.config), "victims": VictimObservation(self.config)}

    def _reset_simulation(self, options: dict[str, Any]) -> None:
        given = options.get("victims")
        xy = None if given is None else given_victims(given, self.config)
        self._sim.reset(self.np_random, victims_xy=xy)

    def _terminated(self) -> bool:
        return _victims_of(self._sim).all_found

    def _info(self) -> dict[str, Any]:
        return {**super()._info(), **_victims_of(self._sim).counts()}


def _victims_of(sim: Simulation) -> Victims:
    """The victims of a search simulation (one built with ``victims=True``)."""
    assert sim.victims is not None, "a search simulation has victims"
    return sim.victims


def given_victims(victims: object, config: EnvConfig) -> np.ndarray:
    """The victim positions of ``reset(options={"victims": xy})``, checked.

    Returns:
        ``(n_victims, 2)`` float64 positions (m), a new array.

    Raises:
        ConfigError: If they are not ``config.victims.n_victims`` finite ``(x, y)`` pairs.
    """
    try:
        xy = np.array(victims, dtype=float)
    except (TypeError, ValueError):
        xy = np.full((0,), np.nan)
    n = config.victims.n_victims
    if xy.shape != (n, 2) or not np.isfinite(xy).all():
        raise ConfigError(
            f"reset option victims must be {n} finite (x, y) positions in metres (victims.n_victims), "
            f"got an array of shape {xy.shape}"
        )
    return xy
