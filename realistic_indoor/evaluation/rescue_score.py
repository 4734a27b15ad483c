"""A RoboCup Rescue Virtual Robot League style score of a team's run: victims reported, doorways and crossings reached.

The league's 2019 rules score a run from the victims the team reported to its operator, the
reports that were wrong, and how much of the building the robots reached, counted at doorways
and corridor crossings. This module measures those parts in the simulator:

- **Checkpoints** (:func:`checkpoints`) come from the building's doors. A *doorway* is an inside
  door with a room (not a corridor or hall) on at least one side; a *crossing* is an opening
  between two circulation spaces (corridor or hall), where corridors meet, turn or widen. Doors
  to the outside are neither: the team starts at one.
- A checkpoint is **reached** once any robot's centre comes within ``reach_m`` of it
  (:class:`CheckpointTracker`).
- **Victims** count when a finding reached the base station through the links
  (``victims_reported``). The simulated victim sensor never reports a victim that is not
  there, so wrong reports are 0 in this simulator; :func:`rescue_score` takes them for
  callers that model them.

The points per part (:class:`RescueScoreConfig`) are this project's defaults, stated here, not
figures quoted from the rules: 10 per victim reported, -5 per wrong report, 50 for reaching every
checkpoint (shared in proportion), so a team that reaches everything is worth five victims.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from realistic_indoor.building.labels import CIRCULATION_LABELS
from realistic_indoor.checks import require_between

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = ["CheckpointTracker", "Checkpoints", "RescueScoreConfig", "checkpoints", "rescue_score"]


@dataclass(frozen=True)
class RescueScoreConfig:
    """Points of the rescue score and when a checkpoint counts as reached.

    Attributes:
        victim_points: Points per victim reported to the base, in [0, 1000].
        wrong_report_points: Points per wrong report, in [-1000, 0] (a penalty).
        exploration_points: Points for reaching every checkpoint, shared in proportion, in
            [0, 1000].
        reach_m: A checkpoint is reached when a robot's centre comes this close (m), in (0, 10].
    """

    victim_points: float = 10.0
    wrong_report_points: float = -5.0
    exploration_points: float = 50.0
    reach_m: float = 1.0

    def __post_init__(self) -> None:
        owner = "RescueScoreConfig"
        require_between(owner, "victim_points", self.victim_points, 0.0, 1000.0, "points")
        require_between(owner, "wrong_report_points", self.wrong_report_points, -1000.0, 0.0, "points")
        require_between(owner, "exploration_points", self.exploration_points, 0.0, 1000.0, "points")
        require_between(owner, "reach_m", self.reach_m, 0.0, 10.0, "m", low_open=True)


class Checkpoints(NamedTuple):
    """Where a building's doorways and corridor crossings are.

    Attributes:
        doorways: ``(n, 2)`` centres of the inside doors into rooms (m, plan frame).
        crossings: ``(m, 2)`` centres of the openings between two circulation spaces (m).
    """

    doorways: np.ndarray
    crossings: np.ndarray


def checkpoints(building: Building) -> Checkpoints:
    """The doorways and corridor crossings of ``building`` (see the module docstring)."""
    labels = {room.id: room.label for room in building.rooms}
    doorways: list[tuple[float, float]] = []
    crossings: list[tuple[float, float]] = []
    for door in building.doors:
        if door.room_b is None:
            continue
        circulation = (
            labels.get(door.room_a) in CIRCULATION_LABELS and labels.get(door.room_b) in CIRCULATION_LABELS
        )
        (crossings if circulation else doorways).append((door.x, door.y))
    return Checkpoints(
        np.array(doorways, dtype=float).reshape(-1, 2), np.array(crossings, dtype=float).reshape(-1, 2)
    )


class CheckpointTracker:
    """Which of a building's checkpoints the team has reached so far.

    Args:
        points: The building's checkpoints.
        reach_m: How close a robot's centre must come (m).
    """

    def __init__(self, points: Checkpoints, reach_m: float) -> None:
        self.points = points
        self.reach_m = float(reach_m)
        self.doorways = np.zeros(len(points.doorways), dtype=bool)
        self.crossings = np.zeros(len(points.crossings), dtype=bool)

    def add(self, poses: np.ndarray) -> None:
        """Mark the checkpoints within reach of any robot (``(n, >= 2)`` poses, plan frame, m)."""
        xy = np.asarray(poses, dtype=float)[:, :2]
        for reached, where in (
            (self.doorways, self.points.doorways),
            (self.crossings, self.points.crossings),
        ):
            if len(where):
                d = np.hypot(where[:, None, 0] - xy[None, :, 0], where[:, None, 1] - xy[None, :, 1])
                reached |= (d <= self.reach_m).any(axis=1)

    @property
    def doorways_share(self) -> float:
        """Share of the doorways reached (``NaN`` if the building has none)."""
        return float(self.doorways.mean()) if len(self.doorways) else float("nan")

    @property
    def crossings_share(self) -> float:
        """Share of the crossings reached (``NaN`` if the building has none)."""
        return float(self.crossings.mean()) if len(self.crossings) else float("nan")

    @property
    def share(self) -> float:
        """Share of all checkpoints reached, doorways and crossings alike (0 if there are none)."""
        total = len(self.doorways) + len(self.crossings)
        return float((self.doorways.sum() + self.crossings.sum()) / total) if total else 0.0


def rescue_score(
    victims_reported: int,
    checkpoint_share: float,
    wrong_reports: int = 0,
    config: RescueScoreConfig | None = None,
) -> float:
    """The run's score: victims reported and wrong reports at their points, plus the exploration share.

    Args:
        victims_reported: Victims whose finding reached the base station.
        checkpoint_share: Share of the checkpoints reached, in [0, 1].
        wrong_reports: Reports of victims that are not there.
        config: The points (defaults: :class:`RescueScoreConfig`).
    """
    c = config or RescueScoreConfig()
    return float(
        c.victim_points * victims_reported
        + c.wrong_report_points * wrong_reports
        + c.exploration_points * checkpoint_share
    )
