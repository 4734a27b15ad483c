"""How a team's robots share maps: the batch's map layout, and the merges links call for.

- ``shared``: one map; every robot's scans go into it and every robot sees it.
- ``own``: each robot its own map, never shared; a team map integrates every robot's scans (the
  team's coverage), which no robot sees.
- ``comm``: each robot its own map, merged while robots are linked directly or through others
  (:func:`~realistic_indoor.teams.links.connected`): the robots of one component of the link
  graph share one map, as in ``shared``, and keep a copy of it when the component splits. When
  two components join, each gets what the other knew (the merge's cells count as sent). A team
  map integrates every scan, as with ``own``.

Relative start poses are known (the robots start together at the base), so merging maps is
laying one on the other.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from realistic_indoor.sim.batch import Batch

__all__ = ["TeamMaps"]


class TeamMaps:
    """Which map each robot of a team sees, and how the maps change as the links do.

    Args:
        n: Robots in the team (robots ``0..n-1`` of one building slot).
        sharing: ``"shared"``, ``"own"`` or ``"comm"``.

    Attributes:
        robot_map: ``(n,)`` the map each robot sees.
        team_map: The map that integrates every robot's scans (the team's coverage).

    With ``comm``, while every robot shares one map that map holds all the team knows (each
    merge brought in all a robot had seen, and every scan since went into it), so the team map
    takes no scans then and :attr:`coverage_map` is the shared one; the team map is brought up
    to date (a copy) when the team splits again. The same cells, one map update a scan fewer.
    """

    def __init__(self, n: int, sharing: str) -> None:
        self.n = n
        self.sharing = sharing
        if sharing == "shared":
            self.robot_map = np.zeros(n, dtype=np.int64)
            self.team_map = 0
        else:
            self.robot_map = np.arange(n, dtype=np.int64)
            self.team_map = n

    @property
    def n_maps(self) -> int:
        """Maps the batch holds: one shared, or one per robot and the team map."""
        return 1 if self.sharing == "shared" else self.n + 1

    @property
    def together(self) -> bool:
        """Whether every robot sees one map (always with ``shared``)."""
        return bool((self.robot_map == self.robot_map[0]).all())

    @property
    def coverage_map(self) -> int:
        """The map that holds all the team knows: the team map, or the one all robots share."""
        return int(self.robot_map[0]) if self.sharing != "own" and self.together else self.team_map

    def map_scans(self) -> list[list[int]]:
        """For each map, the robots whose scans it integrates, in order (the batch's ``map_scans``)."""
        if self.sharing == "shared":
            return [list(range(self.n))]
        own = [[int(i) for i in np.flatnonzero(self.robot_map == m)] for m in range(self.n)]
        team = [] if self.sharing == "comm" and self.together else list(range(self.n))
        return [*own, team]

    def reset(self) -> None:
        """Back to the start's layout (with ``comm``: each robot its own map again)."""
        if self.sharing != "shared":
            self.robot_map = np.arange(self.n, dtype=np.int64)

    def relink(self, batch: Batch, components: np.ndarray) -> int:
        """With ``comm``, give the robots of each component of the link graph one map.

        A map whose robots are now in two components is copied for all but the component of its
        lowest robot; then the maps of each component are merged into the map of its lowest
        robot, and its robots pointed at it. The batch's layout is updated.

        Args:
            batch: The team's batch (robots ``0..n-1``).
            components: ``(n,)`` the component of each robot.

        Returns:
            Map cells sent: for each merge, the reachable floor cells each side knew that the
            other did not.
        """
        if self.sharing != "comm":
            return 0
        grouped = self.robot_map[:, None] == self.robot_map[None, :]
        if np.array_equal(grouped, components[:, None] == components[None, :]):
            return 0  # the links join the robots as their maps do: nothing to split or merge
        before = self.robot_map.copy()
        if self.together:
            batch.copy_map(self.team_map, int(self.robot_map[0]))  # the team map takes scans again
        self._split(batch, components)
        sent = self._merge(batch, components)
        if not np.array_equal(before, self.robot_map):
            batch.set_maps(self.robot_map, self.map_scans())
        return sent

    def _split(self, batch: Batch, components: np.ndarray) -> None:
        for m in range(self.n):
            robots = np.flatnonzero(self.robot_map == m)
            if len(robots) < 2:
                continue
            keep = components[robots[0]]
            for part in sorted(set(components[robots]) - {keep}):
                free = self._free_map()
                batch.copy_map(free, m)
                self.robot_map[robots[components[robots] == part]] = free

    def _merge(self, batch: Batch, components: np.ndarray) -> int:
        sent = 0
        for c in np.unique(components):
            robots = np.flatnonzero(components == c)
            target = int(self.robot_map[robots[0]])
            for m in sorted(set(self.robot_map[robots].tolist()) - {target}):
                known_target, known_m = int(batch.observed[target]), int(batch.observed[m])
                new = batch.merge_map(target, m)
                sent += new + (known_target - (known_m - new))  # each side's cells the other lacked
                self.robot_map[self.robot_map == m] = target
        return sent

    def _free_map(self) -> int:
        """A robot map no robot sees."""
        used = set(self.robot_map.tolist())
        return next(m for m in range(self.n) if m not in used)
