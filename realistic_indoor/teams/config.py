"""A team's configuration: how many robots, their radio links and how they share maps."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from realistic_indoor.checks import require_between, require_int
from realistic_indoor.errors import ConfigError
from realistic_indoor.teams.links import LinkModel, WssLinks, as_link_model

__all__ = ["MAP_SHARING", "MAX_ROBOTS", "TeamConfig"]

MAX_ROBOTS = 16
"""Most robots in a team: the competition's teams had a handful; the pair search of the contact
solver and of the links grows with the square of the team."""
MAP_SHARING = ("shared", "own", "comm")
"""How a team's robots share maps: one map for all (``shared``), each its own (``own``), or each
its own, merged while linked directly or through others (``comm``)."""


@dataclass(frozen=True)
class TeamConfig:
    """A team of robots in one building, beside a base station at its entrance.

    Attributes:
        n_robots: Robots in the team, an integer in [1, :data:`MAX_ROBOTS`].
        comm: The radio links (:mod:`realistic_indoor.teams.links`): a model, or the name of one
            (``"unlimited"``, ``"none"``, ``"range"``, ``"los"``, ``"wss"``) for its defaults.
            Default: the WSS model (log-distance path loss and 6.3 dB per wall).
        map_sharing: One of :data:`MAP_SHARING` (default ``"comm"``).
        spacing_m: Gap between two robots' discs at the start (m), in [0, 2].
        base_offset_m: How far outside the entrance the base station stands, from the door's
            centre (m), in [0, 10].
    """

    n_robots: int = 2
    comm: Any = field(default_factory=WssLinks)
    map_sharing: str = "comm"
    spacing_m: float = 0.2
    base_offset_m: float = 0.5

    def __post_init__(self) -> None:
        require_int("TeamConfig", "n_robots", self.n_robots, 1, MAX_ROBOTS)
        object.__setattr__(self, "comm", as_link_model(self.comm))
        if self.map_sharing not in MAP_SHARING:
            raise ConfigError(
                f"TeamConfig.map_sharing must be one of {', '.join(MAP_SHARING)}, got {self.map_sharing!r}"
            )
        require_between("TeamConfig", "spacing_m", self.spacing_m, 0.0, 2.0, "m")
        require_between("TeamConfig", "base_offset_m", self.base_offset_m, 0.0, 10.0, "m")

    @property
    def links(self) -> LinkModel:
        """The link model (``comm`` after checking)."""
        return self.comm
