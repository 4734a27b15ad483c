"""A native vector environment: N exploring robots, each in its own building, one compiled step.

``gym.make_vec("OfficeExplore-v0", num_envs=N)`` returns :class:`BatchedExploreEnv` through the
id's ``vector_entry_point``. Every step runs physics, laser, map update, local view and reward
terms of all sub-environments in one multi-threaded numba call (:mod:`realistic_indoor.sim.batch`);
only resets (a new building: generation and world build) run in Python, one sub-environment at a
time.
"""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import numba
import numpy as np
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space
from numba.typed import List

from realistic_indoor.checks import require_int
from realistic_indoor.envs._vector_kernels import account, observe
from realistic_indoor.envs.actions import ActionMap
from realistic_indoor.envs.config import EnvConfig, require_reset_options, require_task_fields
from realistic_indoor.envs.observations import POSE_LIMIT_M, explore_observations
from realistic_indoor.envs.presets import base_config
from realistic_indoor.envs.rewards import EXPLORE_TERMS, term_weights
from realistic_indoor.envs.source import episode_building
from realistic_indoor.envs.vector_views import RENDER_MODES, SubEnvViews, require_render_mode
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.batch import (
    RESET,
    SKIP,
    STEP,
    Batch,
    StepOutputs,
    step_batch,
    step_batch_serial,
    step_constants,
)
from realistic_indoor.sim.disc_physics import THETA, X, Y
from realistic_indoor.sim.lidar import draw_noise
from realistic_indoor.sim.world import World

__all__ = ["INFO_KEYS", "ROBOTS_PER_THREAD", "BatchedExploreEnv", "step_threads"]

INFO_KEYS = ("coverage", "observed_area_m2", "path_length_m", "collisions")
"""Arrays of ``info`` after every step and reset (with Gymnasium's ``_key`` masks)."""
ROBOTS_PER_THREAD = 16
"""Fewest robots per numba thread: a step of a few robots on two threads of a loaded 2-core
machine took 9 ms (waking the other thread), against 0.1 ms per robot on one."""


def step_threads(num_envs: int, available: int) -> int:
    """The numba threads a step of ``num_envs`` robots runs on when ``available`` may be used.

    One per :data:`ROBOTS_PER_THREAD` robots, at most ``available``. The environment first asks
    with numba's most (``NUMBA_NUM_THREADS``): for 1 the step runs on the calling thread
    (:func:`~realistic_indoor.sim.batch.step_batch_serial`) and numba's thread pool is not
    started; otherwise it asks again with the current ``numba.get_num_threads()``, and for 1
    runs the serial kernel too.
    """
    return max(1, min(available, num_envs // ROBOTS_PER_THREAD))


class BatchedExploreEnv(VectorEnv):
    """``num_envs`` exploration robots, each in its own building, stepped in one compiled call.

    The same task, spaces, rewards and episode ends as :class:`~realistic_indoor.envs.ExploreEnv`
    (see there); what differs:

    - **Physics**: the compiled disc of :mod:`realistic_indoor.sim.disc_physics` only, the
      single environment's default: sub-environment ``k`` then runs exactly the episode of an
      ``ExploreEnv`` seeded as it is (``RobotConfig(physics="pymunk")`` is refused here).
    - **Autoreset**: Gymnasium's next-step mode (``metadata["autoreset_mode"]``). The step that
      ends a sub-environment's episode returns its last observation; its next step ignores the
      action, starts a new episode (a new building drawn from that sub-environment's random
      generator) and returns the first observation with reward 0 and both flags false.
    - **info**: arrays over the sub-environments, each with Gymnasium's boolean ``_key`` mask:
      ``coverage``, ``observed_area_m2``, ``path_length_m``, ``collisions``, and after a step
      ``rewards`` (a dict of the reward terms, each an array).
    - **Seeds**: ``reset(seed=s)`` seeds sub-environment ``k`` with ``s + k`` (or ``seed`` as a
      list, one per sub-environment); sub-environment ``k`` then draws the same building and the
      same laser noise as ``ExploreEnv`` reset with that seed.
    - **Rendering**: ``render_mode="rgb_array"`` makes :meth:`render` return a tuple of frames,
      sub-environment ``k``'s being ``ExploreEnv``'s top view of the same episode (its own
      building's size); ``"human"`` shows them side by side in one pygame window.

    Args:
        num_envs: Number of sub-environments (robots).
        config: The configuration (as :class:`ExploreEnv`); ``None`` for the preset's.
        max_episode_steps: The registered step limit; sets ``max_steps`` when given.
        preset: A registered id whose configuration is the base when ``config`` is not given
            (``gym.make_vec`` passes it).
        render_mode: ``None``, ``"rgb_array"`` or ``"human"`` (see Rendering above).
        **overrides: Fields of :class:`~realistic_indoor.envs.config.EnvConfig`.

    Raises:
        ConfigError: For a bad configuration or render mode, or ``num_envs`` below 1.
    """

    metadata = {"render_modes": list(RENDER_MODES), "autoreset_mode": AutoresetMode.NEXT_STEP}
    task = "explore"
    """The task whose configuration fields apply (:data:`~realistic_indoor.envs.config.TASK_FIELDS`)."""
    term_names: tuple[str, ...] = EXPLORE_TERMS
    """The reward terms, in the order the single environment sums them."""
    reset_options: frozenset[str] = frozenset({"reset_mask", "building"})
    """Keys ``reset(options=...)`` accepts."""

    def __init__(
        self,
        num_envs: int = 1,
        config: EnvConfig | None = None,
        max_episode_steps: int | None = None,
        preset: str | None = None,
        render_mode: str | None = None,
        **overrides: Any,
    ) -> None:
        require_int("BatchedExploreEnv", "num_envs", num_envs, 1)
        require_render_mode(render_mode)
        num_envs = int(num_envs)
        if max_episode_steps is not None:
            overrides = {"max_steps": max_episode_steps, **overrides}
        self.config = base_config(config, preset).replace(**overrides)
        require_task_fields(self.config, self.task, overrides)
        if refused := self.config.batch_refusal():
            kind, what = refused
            mode = "'async' (one process per copy)" if kind == "actions" else "'sync'"
            raise ConfigError(
                f"the native vector env cannot run {what}; use gym.make_vec(..., vectorization_mode={mode})"
            )
        self.num_envs = num_envs
        self.render_mode = render_mode
        self.metadata = {**self.metadata, "render_fps": self.config.robot.control_hz}
        self._source = self.config.source.generator()
        self._actions = ActionMap(
            self.config.action_type, self.config.robot.max_speed_m_s, self.config.robot.max_turn_rate_rad_s
        )
        self.single_action_space = self._actions.space
        self.action_space = batch_space(self.single_action_space, num_envs)
        parts = self._observation_parts()
        self.single_observation_space = gym.spaces.Dict({k: p.space for k, p in parts.items()})
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self._init_arrays()

    def _init_arrays(self) -> None:
        c, n = self.config, self.num_envs
        self._constants = step_constants(c.robot, c.world, c.lidar, c.local_map)
        self._params = self._constants.params
        self._pool = int(self._constants.local[0])
        self._batch = Batch(n)
        self._mode = np.zeros(n, dtype=np.int64)
        self._commands = np.zeros((n, 2))
        self._noise = np.zeros((n, c.lidar.n_beams))
        self._out = StepOutputs.zeros(n, c.lidar.n_beams, c.local_map.size_px, len(self.term_names))
        self._scan_m, self._local_map, self._terms, self._motion = self._out[:4]
        self._steps = np.zeros(n, dtype=np.int64)
        self._path = np.zeros(n)
        self._collisions = np.zeros(n, dtype=np.int64)
        self._autoreset = np.zeros(n, dtype=bool)
        self._rngs: list[np.random.Generator] = []
        self._rng_list: List | None = None  # the same generators in a numba typed List, for draw_noise
        self._max_steps = c.max_steps  # at most MAX_STEPS (1,000,000): an int64 step count holds it
        self._scan_scale = np.float32(1.0 / c.lidar.max_range_m)
        self._weights = term_weights(c.rewards, self.term_names)
        self._slots: dict[str, np.ndarray] | None = None
        self._views = None if self.render_mode is None else SubEnvViews(n, c.lidar, c.robot.radius_m)

    # -- the Gymnasium API ----------------------------------------------------------------------
    def reset(
        self, *, seed: int | list[int | None] | None = None, options: dict[str, Any] | None = None
    ) -> tuple[dict[str, np.ndarray], dict[str, Any]]:
        """Start an episode in every sub-environment (or those of a mask), each in a new building.

        Args:
            seed: ``s`` seeds sub-environment ``k`` with ``s + k``; a list gives one seed each
                (``None`` entries draw fresh entropy); ``None`` keeps the generators (fresh ones
                on the first reset). With a mask, only the masked sub-environments are seeded.
            options: ``None``, or any of ``{"reset_mask": m}``, ``m`` a ``(num_envs,)`` bool
                array with at least one ``True``: only those sub-environments start a new
                episode (Gymnasium's partial reset), the others keep their state and last
                observation; ``{"building": b}``: the sub-environments started run this episode
                in building ``b`` instead of drawing one, as ``ExploreEnv.reset`` does.

        Returns:
            The batched first observations and ``info`` (arrays), which adds to a step's info
            ``start_pose``: ``(num_envs, 3)`` where each robot starts, ``(x m, y m, heading
            rad)`` in its plan's frame, as the single environment's ``reset`` gives it.

        Raises:
            ConfigError: For bad seeds, an unknown option, a bad mask or a building (given or
                drawn) that is not a ``Building``.
            ResetNeeded: For a mask before the first full reset.
        """
        seeds = self._seeds(seed)
        mask = self._reset_mask(options)
        if not self._rngs and not mask.all():
            raise gym.error.ResetNeeded("the first reset() starts every sub-environment: drop the reset_mask")
        previous = self._rngs, self._rng_list
        if not self._rngs:
            self._rngs = [np.random.default_rng(s) for s in seeds or [None] * self.num_envs]
        elif seeds is not None:
            self._rngs = [np.random.default_rng(seeds[k]) if mask[k] else g for k, g in enumerate(self._rngs)]
        if self._rngs is not previous[0]:
            self._rng_list = List(self._rngs)
        try:
            self._start(mask, options or {})
        except Exception:
            self._rngs, self._rng_list = previous  # a refused reset leaves the generators as they were
            raise
        if self.render_mode == "human":
            self.render()
        progress = self._account(np.zeros(self.num_envs, dtype=bool))
        info = self._info(progress, rewards=False, mask=mask)
        start = self._slot_arrays()
        info["start_pose"] = np.stack([start["x"], start["y"], start["heading"]], axis=1)
        info["_start_pose"] = info["_coverage"]
        return self._observe(), info

    def step(
        self, actions: np.ndarray
    ) -> tuple[dict[str, np.ndarray], np.ndarray, np.ndarray, np.ndarray, dict[str, Any]]:
        """Step every sub-environment; those whose episode ended last step start a new one.

        Raises:
            ActionError: If ``actions`` is not a batch of valid actions.
            ResetNeeded: Before the first :meth:`reset`.
        """
        if not self._rngs:
            raise gym.error.ResetNeeded("call reset() before step()")
        self._commands[:] = self._actions.commands(actions, self.num_envs)
        self._mode[:] = np.where(self._autoreset, RESET, STEP)
        if self._autoreset.any():  # every next building drawn and built first, as in reset
            starting = [int(k) for k in np.flatnonzero(self._autoreset)]
            worlds = self._next_worlds(starting, None)
            for k in starting:
                self._reset_one(k, worlds[k])
        self._run()
        stepped = self._mode == STEP
        if self._views is not None:
            self._views.moved(stepped, self._batch.phys[:, [X, Y]])
        self._sense(stepped)
        progress = self._account(stepped)
        reward, truncated, coverage = progress[0], progress[1], progress[2]
        terminated = stepped & self._done(coverage)  # truncated also when terminated, as TimeLimit
        self._autoreset = terminated | truncated
        info = self._info(progress)
        if self.render_mode == "human":
            self.render()
        return self._observe(), reward, terminated, truncated, info

    def render(self) -> tuple[np.ndarray, ...] | None:
        """Top views of the sub-environments' episodes (as the single environment draws them).

        Returns:
            With ``render_mode="rgb_array"``, one ``(H, W, 3)`` uint8 frame per sub-environment,
            each of its own building's size; with ``"human"``, ``None``, the frames being shown
            side by side in a pygame window (``reset`` and ``step`` call this themselves).

        Raises:
            ResetNeeded: Before the first :meth:`reset` (or after :meth:`close`).
            DependencyNotInstalled: If ``render_mode="human"`` and pygame is not installed
                (``pip install "realistic-indoor[viz]"``).
        """
        if self._views is None:
            gym.logger.warn('render() needs a render mode: gym.make_vec(..., render_mode="rgb_array")')
            return None
        if not self._rngs:
            raise gym.error.ResetNeeded("call reset() before render()")
        b = self._batch
        frames = tuple(
            self._views.frame(
                k,
                b.worlds[b.robot_building[k]],
                b.grids[k],
                self._pose(k),
                self._scan_m[k],
                self._victims_of(k),
            )
            for k in range(self.num_envs)
        )
        if self.render_mode == "rgb_array":
            return frames
        title = f"realistic-indoor: {self.spec.id if self.spec else type(self).__name__} x {self.num_envs}"
        self._views.show(frames, title, self.metadata["render_fps"])
        return None

    def restart(self, indices: np.ndarray) -> dict[str, np.ndarray]:
        """Start new episodes now in some sub-environments (same-step autoreset, as SB3 wants).

        The sub-environments ``indices`` draw their next building and take their first scan;
        the others keep their state and last observation. A pending next-step autoreset of a
        restarted sub-environment is cancelled.

        Args:
            indices: Sub-environment indices (ints).

        Returns:
            The batched observations of every sub-environment.

        Raises:
            ConfigError: If an index is not that of a sub-environment.
            ResetNeeded: Before the first :meth:`reset` (or after :meth:`close`).
        """
        if not self._rngs:
            raise gym.error.ResetNeeded("call reset() before restart()")
        chosen = np.unique(np.asarray(indices))
        if chosen.size and (
            chosen.dtype.kind not in "iu" or chosen.min() < 0 or chosen.max() >= self.num_envs
        ):
            raise ConfigError(
                f"restart() takes sub-environment indices in 0..{self.num_envs - 1}, got {indices!r}"
            )
        mask = np.zeros(self.num_envs, dtype=bool)
        mask[chosen.astype(np.int64)] = True
        self._start(mask)
        return self._observe()

    def close_extras(self, **kwargs: Any) -> None:
        """Free the worlds and close the window; a later step or restart asks for a reset first."""
        if self._views is not None:
            self._views.close()
        self._batch = Batch(self.num_envs)
        self._slots = None
        self._rngs = []
        self._rng_list = None

    def __getstate__(self) -> dict[str, Any]:
        """The state to pickle (``pickle``, ``copy.deepcopy``): the typed list of generators left out."""
        return {**self.__dict__, "_rng_list": None}

    def __setstate__(self, state: dict[str, Any]) -> None:
        """Restore a pickled state: the copy goes on exactly as the original would."""
        self.__dict__.update(state)
        if self._rngs:
            self._rng_list = List(self._rngs)

    # -- state a user may inspect --------------------------------------------------------------------
    @property
    def buildings(self) -> list[Any]:
        """The building of each sub-environment's current episode."""
        return [None if w is None else w.building for w in self._batch.worlds]

    @property
    def poses(self) -> np.ndarray:
        """``(num_envs, 3)`` robot poses ``(x m, y m, heading rad)`` in the plans' frames."""
        return self._batch.phys[:, [X, Y, THETA]].copy()

    @property
    def nbytes(self) -> int:
        """Memory held by the batch's worlds, maps and arrays (bytes)."""
        return self._batch.nbytes

    # -- what a task adds (search: victims) --------------------------------------------------------
    def _observation_parts(self) -> dict[str, Any]:
        """The parts of one sub-environment's observation (as the single environment's)."""
        return explore_observations(self.config)

    def _sense(self, stepped: np.ndarray) -> None:
        """After the compiled step: what the task senses in Python (nothing for exploration)."""

    def _done(self, coverage: np.ndarray) -> np.ndarray:
        """``(num_envs,)`` whether each sub-environment's task is complete, given its coverage."""
        return self.config.explored(coverage)

    def _victims_of(self, k: int) -> tuple[np.ndarray, np.ndarray] | None:
        """Sub-environment ``k``'s victim positions and found flags, drawn by :meth:`render`."""
        return None

    # -- internals -----------------------------------------------------------------------------------
    def _start(self, mask: np.ndarray, options: dict[str, Any] | None = None) -> None:
        """Start new episodes in the sub-environments of ``mask``, cancelling their pending autoresets.

        ``options`` are ``reset``'s (checked): each started sub-environment gets them. Every
        building is drawn and its world built before any sub-environment changes, so that a
        building that cannot be used changes nothing (its error is raised, the generators put
        back as they were).
        """
        started = [int(k) for k in np.flatnonzero(mask)]
        worlds = self._next_worlds(started, options)
        self._mode[:] = np.where(mask, RESET, SKIP)
        for k in started:
            self._reset_one(k, worlds[k], options)
        self._autoreset[mask] = False
        if mask.any():
            self._run()

    def _reset_mask(self, options: dict[str, Any] | None) -> np.ndarray:
        """The sub-environments a reset starts: ``options["reset_mask"]``, checked, or all."""
        options = require_reset_options(options, self.reset_options)
        if "reset_mask" not in options:
            return np.ones(self.num_envs, dtype=bool)
        mask = options["reset_mask"]
        if not (isinstance(mask, np.ndarray) and mask.dtype == np.bool_ and mask.shape == (self.num_envs,)):
            raise ConfigError(
                f"options['reset_mask'] must be a ({self.num_envs},) bool array, got {type(mask).__name__} "
                f"{getattr(mask, 'dtype', '')} {getattr(mask, 'shape', '')}"
            )
        if not mask.any():
            raise ConfigError("options['reset_mask'] selects no sub-environment: set at least one True")
        return mask

    def _seeds(self, seed: int | list[int | None] | None) -> list[int | None] | None:
        if seed is None:
            return None
        if isinstance(seed, (int, np.integer)) and not isinstance(seed, bool):
            seeds: list[int | None] = [int(seed) + k for k in range(self.num_envs)]
        else:
            seeds = list(seed)
            if len(seeds) != self.num_envs:
                raise ConfigError(f"reset(seed=...) needs {self.num_envs} seeds, got {len(seeds)}")
        for s in seeds:
            if s is not None:
                require_int("BatchedExploreEnv.reset", "seed", s, 0)
        return seeds

    def _next_worlds(self, started: list[int], options: dict[str, Any] | None) -> dict[int, World]:
        """The world of each started sub-environment's next episode, built only if no slot holds it.

        The building is ``options["building"]`` or the next one drawn from the sub-environment's
        generator. On an error the generators drawn from are put back as they were.
        """
        given = (options or {}).get("building")
        if given is not None:
            given = episode_building(given, given=True)
        states = {k: self._rngs[k].bit_generator.state for k in started}
        held = {id(w.building): w for w in self._batch.worlds if w is not None}
        worlds: dict[int, World] = {}
        try:
            for k in started:
                building = episode_building(self._source(self._rngs[k]) if given is None else given)
                if id(building) not in held:
                    held[id(building)] = World(building, self.config.world)
                worlds[k] = held[id(building)]
            if given is not None:
                self._check_world(worlds[started[0]], options)
        except Exception:
            for k, state in states.items():
                self._rngs[k].bit_generator.state = state
            raise
        return worlds

    def _check_world(self, world: World, options: dict[str, Any] | None) -> None:
        """Refuse a given building the task cannot run in (nothing for exploration)."""

    def _reset_one(self, k: int, world: World, options: dict[str, Any] | None = None) -> None:
        """Start sub-environment ``k``'s next episode in ``world`` (:meth:`_next_worlds`).

        ``options`` are ``reset``'s, for what a task adds (search: victims).
        """
        batch = self._batch
        if batch.worlds[k] is not world:
            batch.load(k, world, self._params[0], self._pool)
        batch.reset_robot(k)
        if self._views is not None:
            self._views.start(k, (float(batch.phys[k, X]), float(batch.phys[k, Y])))
        self._slots = None  # its building's start and floor may have changed
        self._steps[k] = 0
        self._path[k] = 0.0
        self._collisions[k] = 0
        self._noise_for(k)

    def _noise_for(self, k: int) -> None:
        if self.config.lidar.noise_std_m > 0:
            self._rngs[k].standard_normal(out=self._noise[k])

    def _run(self) -> None:
        if self.config.lidar.noise_std_m > 0:
            draw_noise(self._rng_list, self._mode == STEP, self._noise)
        b = self._batch
        # numba's thread pool is asked only when it could give more than one thread
        # (get_num_threads starts it, and its OpenMP threads slow torch down in the same process)
        used = step_threads(self.num_envs, numba.config.NUMBA_NUM_THREADS)
        if used > 1:
            outer = numba.get_num_threads()
            used = step_threads(self.num_envs, outer)
        if used == 1:
            # the serial kernel: numba's parallel one on one thread ran a robot-step half as slow
            # again (97 against 65 us, 64 robots, 2-core AMD EPYC, OpenMP layer)
            self._step_batch(b, step_batch_serial)
            return
        numba.set_num_threads(used)
        try:
            self._step_batch(b, step_batch)
        finally:
            numba.set_num_threads(outer)

    def _step_batch(self, b: Batch, kernel: Any) -> None:
        b.step(kernel, self._mode, self._commands, self._noise, self._constants, self._out)

    def _pose(self, k: int) -> tuple[float, float, float]:
        """Sub-environment ``k``'s robot pose ``(x m, y m, heading rad)``."""
        phys = self._batch.phys
        return (float(phys[k, X]), float(phys[k, Y]), float(phys[k, THETA]))

    def _slot_arrays(self) -> dict[str, np.ndarray]:
        """Per sub-environment, what its building slot holds: start pose, floor, cell area.

        Kept until a sub-environment resets (its building may change): the step reads them
        through one array each instead of indexing the slot table every time.
        """
        if self._slots is None:
            meta = self._batch.building_meta[self._batch.robot_building]
            heading = meta[:, 6]
            self._slots = {
                "x": meta[:, 4],
                "y": meta[:, 5],
                "heading": heading,
                "cos": np.cos(heading),
                "sin": np.sin(heading),
                "reachable": meta[:, 3],
                "cell_m2": meta[:, 2] ** 2,
            }
        return self._slots

    def _account(self, stepped: np.ndarray) -> tuple[np.ndarray, ...]:
        """Count the step of the sub-environments ``stepped``: :func:`~._vector_kernels.account`'s arrays."""
        slots = self._slot_arrays()
        return account(
            stepped, self._terms, self._weights, self._motion, self._batch.observed, slots["reachable"],
            slots["cell_m2"], self._max_steps, self._steps, self._path, self._collisions,
        )  # fmt: skip

    def _observe(self) -> dict[str, np.ndarray]:
        start = self._slot_arrays()
        scan, local_map, velocity, pose = observe(
            self._batch.phys, start["x"], start["y"], start["heading"], start["cos"], start["sin"],
            self._actions.limits, POSE_LIMIT_M, self._scan_m, self._scan_scale, self._local_map,
        )  # fmt: skip
        return {"scan": scan, "local_map": local_map, "velocity": velocity, "pose": pose}

    def _info(
        self, progress: tuple[np.ndarray, ...], rewards: bool = True, mask: np.ndarray | None = None
    ) -> dict[str, Any]:
        """``info`` from :meth:`_account`'s arrays; with ``rewards``, the step's reward terms too.

        ``mask`` marks the sub-environments the info is about (Gymnasium's ``_key`` arrays): all
        after a step, the ones started after a partial reset.
        """
        _, _, coverage, observed_m2, path, collisions, by_term = progress
        values = {
            "coverage": coverage,
            "observed_area_m2": observed_m2,
            "path_length_m": path,
            "collisions": collisions,
        }
        mask = np.ones(self.num_envs, dtype=bool) if mask is None else mask.copy()
        info: dict[str, Any] = {}
        for key, value in values.items():
            info[key] = value
            info[f"_{key}"] = mask
        if rewards:
            info["rewards"] = dict(zip(self.term_names, by_term, strict=True))
            info["_rewards"] = mask
        return info
