"""The native vector environment of victim search: the batched exploration step, then victims.

``gym.make_vec("OfficeSearch-v0", num_envs=N)`` returns :class:`BatchedSearchEnv`. Physics,
laser, map and local view of all robots run in the one compiled call of
:class:`~realistic_indoor.envs.vector.BatchedExploreEnv`; the victim sensor then looks, robot by
robot, with the building's compiled line of sight (a few microseconds each).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from realistic_indoor.envs.observations import explore_observations
from realistic_indoor.envs.rewards import SEARCH_TERMS
from realistic_indoor.envs.search import VictimObservation, given_victims
from realistic_indoor.envs.vector import BatchedExploreEnv
from realistic_indoor.sim.victims import Victims, place_victims
from realistic_indoor.sim.world import World

_VICTIM = SEARCH_TERMS.index("victim")
"""The column of the victim term among the reward terms."""

__all__ = ["BatchedSearchEnv"]


class BatchedSearchEnv(BatchedExploreEnv):
    """``num_envs`` search robots, each in its own building, stepped in one compiled call.

    The task, spaces, rewards and episode ends of :class:`~realistic_indoor.envs.SearchEnv`
    (victims placed at each reset, found when the sensor first sees them; the episode ends when
    all are found), batched as :class:`~realistic_indoor.envs.vector.BatchedExploreEnv` batches
    exploration: next-step autoreset, ``info`` as arrays (adding ``victims_found`` and
    ``victims_total``), ``reset(seed=s)`` seeding sub-environment ``k`` with ``s + k`` so that
    it runs the episode of a ``SearchEnv`` reset with that seed, victims included.

    Args:
        num_envs: Number of sub-environments (robots).
        config: The configuration (as :class:`SearchEnv`); ``None`` for the preset's.
        max_episode_steps: The registered step limit; sets ``max_steps`` when given.
        preset: A registered id whose configuration is the base when ``config`` is not given.
        render_mode: ``None``, ``"rgb_array"`` or ``"human"`` (as the exploration one's; victims
            drawn as ``SearchEnv`` draws them).
        **overrides: Fields of :class:`~realistic_indoor.envs.config.EnvConfig`.
    """

    task = "search"
    term_names = SEARCH_TERMS
    reset_options = frozenset({"reset_mask", "building", "victims"})

    def __init__(self, num_envs: int = 1, config: Any = None, max_episode_steps: int | None = None,
                 preset: str | None = None, render_mode: str | None = None, **overrides: Any) -> None:  # fmt: skip
        super().__init__(num_envs, config, max_episode_steps, preset, render_mode, **overrides)
        self._victims = [Victims(self.config.victims) for _ in range(num_envs)]
        self._victim_view = VictimObservation(self.config)

    @property
    def victims(self) -> list[tuple[np.ndarray, np.ndarray]]:
        """Each sub-environment's ``(positions (N, 2) m, found (N,) bool)`` (copies)."""
        return [(v.xy.copy(), v.found.copy()) for v in self._victims]

    def _observation_parts(self) -> dict[str, Any]:
        return {**explore_observations(self.config), "victims": VictimObservation(self.config)}

    def _reset_one(self, k: int, world: World, options: dict[str, Any] | None = None) -> None:
        super()._reset_one(k, world, options)  # the laser noise of the first scan is drawn: then the victims
        world = self._batch.worlds[k]
        given = (options or {}).get("victims")
        if given is None:
            xy = place_victims(world, self._rngs[k], self.config.victims)
        else:
            xy = given_victims(given, self.config)
        self._victims[k].reset(xy, world.raycaster, self._pose(k))

    def _check_world(self, world: World, options: dict[str, Any] | None) -> None:
        if (options or {}).get("victims") is None:  # rooms to place them in (a throwaway draw)
            place_victims(world, np.random.default_rng(0), self.config.victims)

    def _reset_mask(self, options: dict[str, Any] | None) -> np.ndarray:
        mask = super()._reset_mask(options)
        if (options or {}).get("victims") is not None:
            given_victims(options["victims"], self.config)  # refused before any sub-environment resets
        return mask

    def _sense(self, stepped: np.ndarray) -> None:
        self._terms[:, _VICTIM] = 0.0
        for k in np.flatnonzero(stepped):
            world = self._batch.worlds[self._batch.robot_building[k]]
            self._terms[k, _VICTIM] = self._victims[k].look(world.raycaster, self._pose(int(k)))

    def _done(self, coverage: np.ndarray) -> np.ndarray:
        return np.array([v.all_found for v in self._victims])

    def _observe(self) -> dict[str, np.ndarray]:
        obs = super()._observe()
        obs["victims"] = np.stack(
            [self._victim_view.encode(self._pose(k), v) for k, v in enumerate(self._victims)]
        )
        return obs

    def _info(
        self, progress: tuple[np.ndarray, ...], rewards: bool = True, mask: np.ndarray | None = None
    ) -> dict[str, Any]:
        info = super()._info(progress, rewards, mask)
        mask = info["_coverage"]
        counts = [v.counts() for v in self._victims]
        for key in ("victims_found", "victims_total"):
            info[key] = np.array([c[key] for c in counts])
        info["_victims_found"] = info["_victims_total"] = mask
        return info

    def _victims_of(self, k: int) -> tuple[np.ndarray, np.ndarray]:
        v = self._victims[k]
        return v.xy.copy(), v.found.copy()
