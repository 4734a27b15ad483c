"""Radio links between the robots of a team and its base station: who can talk to whom.

A link model says, from the positions of the team's nodes (its robots, then the base station)
in a world, which pairs are linked directly. Messages may go on through other nodes: two robots
are *connected* when a chain of direct links joins them (:func:`connected`). Each model is a
frozen dataclass whose fields are checked on construction; :func:`as_link_model` turns the
names of :data:`COMM_MODELS` into the default of each.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, ClassVar, Protocol

import numpy as np

from realistic_indoor.checks import require_between, require_int
from realistic_indoor.errors import ConfigError
from realistic_indoor.teams._links_kernels import components, walls_between

if TYPE_CHECKING:
    from realistic_indoor.sim.world import World

__all__ = [
    "COMM_MODELS",
    "LineOfSightLinks",
    "LinkModel",
    "NoLinks",
    "RangeLinks",
    "UnlimitedLinks",
    "WssLinks",
    "as_link_model",
    "connected",
    "walls_crossed",
]


class LinkModel(Protocol):
    """What a link model does: the direct links between nodes at given positions."""

    name: ClassVar[str]

    def linked(self, world: World, xy: np.ndarray) -> np.ndarray:
        """``(k, k)`` bool direct links between the nodes at ``xy`` (``(k, 2)`` m), symmetric, diagonal false."""
        ...


def _no_self(links: np.ndarray) -> np.ndarray:
    np.fill_diagonal(links, False)
    return links


def _distances(xy: np.ndarray) -> np.ndarray:
    """``(k, k)`` distances between the points ``xy`` (m)."""
    diff = xy[:, None, :] - xy[None, :, :]
    return np.hypot(diff[..., 0], diff[..., 1])


def walls_crossed(world: World, xy: np.ndarray) -> np.ndarray:
    """``(k, k)`` int64 walls the straight line between each two points crosses.

    Counted on the world's raster: each run of wall cells the line enters is one wall (two
    rooms' shared wall is one; an open door is none). Points outside the raster count the
    walls on the part of the line inside it.

    Args:
        world: The world.
        xy: ``(k, 2)`` points (m, plan frame).
    """
    raster = world.raster
    cells = (np.asarray(xy, dtype=np.float64) - np.asarray(raster.origin)) / raster.resolution_m
    return walls_between(raster.grid, np.ascontiguousarray(cells))


@dataclass(frozen=True)
class UnlimitedLinks:
    """Every node is linked to every other, wherever they are (the ideal radio)."""

    name: ClassVar[str] = "unlimited"

    def linked(self, world: World, xy: np.ndarray) -> np.ndarray:
        """All pairs linked."""
        return _no_self(np.ones((len(xy), len(xy)), dtype=bool))


@dataclass(frozen=True)
class NoLinks:
    """No node is ever linked to another: each robot knows only what it sees itself."""

    name: ClassVar[str] = "none"

    def linked(self, world: World, xy: np.ndarray) -> np.ndarray:
        """No pair linked."""
        return np.zeros((len(xy), len(xy)), dtype=bool)


@dataclass(frozen=True)
class RangeLinks:
    """Two nodes are linked when they are at most ``range_m`` apart, walls or not (a disc model).

    Attributes:
        range_m: Link range (m), in [0.5, 10000]. Default 20 m: a choice (no source), the order of
            the distance at which :meth:`WssLinks.competition` drops a link behind five walls
            (32 m) and a short indoor Wi-Fi range.
    """

    range_m: float = 20.0
    name: ClassVar[str] = "range"

    def __post_init__(self) -> None:
        require_between("RangeLinks", "range_m", self.range_m, 0.5, 10000.0, "m")

    def linked(self, world: World, xy: np.ndarray) -> np.ndarray:
        """Pairs within range."""
        return _no_self(_distances(xy) <= self.range_m)


@dataclass(frozen=True)
class LineOfSightLinks:
    """Two nodes are linked when no wall stands between them and they are within ``range_m``.

    Attributes:
        range_m: Longest link (m), in [0.5, 10000]; default 10000 m: line of sight alone.
    """

    range_m: float = 10000.0
    name: ClassVar[str] = "los"

    def __post_init__(self) -> None:
        require_between("LineOfSightLinks", "range_m", self.range_m, 0.5, 10000.0, "m")

    def linked(self, world: World, xy: np.ndarray) -> np.ndarray:
        """Pairs within range with no wall between them."""
        return _no_self((walls_crossed(world, xy) == 0) & (_distances(xy) <= self.range_m))


@dataclass(frozen=True)
class WssLinks:
    """Log-distance path loss plus a fixed loss per wall: the USARSim Wireless Simulation Server's model.

    The received power at distance ``d`` through ``n_w`` walls is
    ``P(d) = p_d0_dbm - 10 * exponent * log10(d / d0_m) - min(n_w, max_walls) * wall_loss_db``
    (``P(d0)`` for ``d < d0``; Seidel and Rappaport's partition model, IEEE Trans. Antennas
    Propag. 40(2), 1992, as USARSim's WSS used it); a link holds while ``P >= cutoff_dbm``
    (both ways: the model is symmetric). Walls are counted on the raster (:func:`walls_crossed`).

    Defaults (a 2.4 GHz radio): ``p_d0_dbm`` -20 dBm at ``d0_m`` 1 m, a 20 dBm (100 mW)
    transmitter less the 40 dB free-space loss at 1 m and 2.4 GHz (``20 log10(4 pi d f / c)``);
    ``exponent`` 2, free space between walls, as the multi-wall model of Motley and Keenan
    (Electronics Letters 24(12), 1988) takes it; ``wall_loss_db`` 6.3 dB and ``cutoff_dbm``
    -93 dBm, the WSS's (issue 33); ``max_walls`` 1000, no cap. :meth:`competition` gives the
    settings of the RoboCup Rescue Virtual Robot competition's WSS.

    Attributes:
        p_d0_dbm: Received power at the reference distance (dBm), in [-100, 30].
        d0_m: Reference distance (m), in [0.1, 100].
        exponent: Path loss exponent, in [1, 6].
        wall_loss_db: Loss per wall crossed (dB), in [0, 50].
        max_walls: Walls counted at most (the model's ``C``), an integer in [0, 1000].
        cutoff_dbm: Weakest signal that still links (dBm), in [-150, 0].
    """

    p_d0_dbm: float = -20.0
    d0_m: float = 1.0
    exponent: float = 2.0
    wall_loss_db: float = 6.3
    max_walls: int = 1000
    cutoff_dbm: float = -93.0
    name: ClassVar[str] = "wss"

    def __post_init__(self) -> None:
        require_between("WssLinks", "p_d0_dbm", self.p_d0_dbm, -100.0, 30.0, "dBm")
        require_between("WssLinks", "d0_m", self.d0_m, 0.1, 100.0, "m")
        require_between("WssLinks", "exponent", self.exponent, 1.0, 6.0, "")
        require_between("WssLinks", "wall_loss_db", self.wall_loss_db, 0.0, 50.0, "dB")
        require_int("WssLinks", "max_walls", self.max_walls, 0, 1000)
        require_between("WssLinks", "cutoff_dbm", self.cutoff_dbm, -150.0, 0.0, "dBm")

    @classmethod
    def competition(cls) -> WssLinks:
        """The settings the RoboCup Rescue Virtual Robot competition's WSS shipped with.

        ``ePdo`` -49.5 dBm at ``eDo`` 2 m, ``eN`` 1.0, ``eAttenuationFactor`` 6.3 dB,
        ``eMaxObstacles`` 5, ``eCutoff`` -93 dBm (the WSS configuration file's names). The 6.3 dB
        and -93 dBm are in issue 33; the other four are as the WSS documentation gave them and
        have not been checked against a copy of the file here (docs/teams.md).
        """
        return cls(p_d0_dbm=-49.5, d0_m=2.0, exponent=1.0, wall_loss_db=6.3, max_walls=5, cutoff_dbm=-93.0)

    def signal_dbm(self, world: World, xy: np.ndarray) -> np.ndarray:
        """``(k, k)`` received power between each two nodes (dBm); the diagonal is ``p_d0_dbm``."""
        d = np.maximum(_distances(xy), self.d0_m)
        walls = np.minimum(walls_crossed(world, xy), self.max_walls)
        return self.p_d0_dbm - 10.0 * self.exponent * np.log10(d / self.d0_m) - walls * self.wall_loss_db

    def linked(self, world: World, xy: np.ndarray) -> np.ndarray:
        """Pairs whose signal is at least the cutoff."""
        return _no_self(self.signal_dbm(world, xy) >= self.cutoff_dbm)

    def range_through_m(self, walls: int) -> float:
        """The longest link through ``walls`` walls (m): where ``P`` falls to the cutoff."""
        budget = self.p_d0_dbm - min(walls, self.max_walls) * self.wall_loss_db - self.cutoff_dbm
        return 0.0 if budget < 0 else self.d0_m * 10.0 ** (budget / (10.0 * self.exponent))


_MODELS = {m.name: m for m in (UnlimitedLinks, NoLinks, RangeLinks, LineOfSightLinks, WssLinks)}
COMM_MODELS: tuple[str, ...] = tuple(_MODELS)
"""The names ``comm=`` takes: ``unlimited``, ``none``, ``range``, ``los``, ``wss``."""


def as_link_model(comm: str | LinkModel) -> LinkModel:
    """A link model from its name (its defaults) or a model given as it is.

    Raises:
        ConfigError: For an unknown name or anything else.
    """
    if isinstance(comm, str) and comm in _MODELS:
        return _MODELS[comm]()
    if isinstance(comm, tuple(_MODELS.values())):
        return comm
    raise ConfigError(
        f"comm must be one of {', '.join(COMM_MODELS)} or a link model such as WssLinks(), got {comm!r}"
    )


def connected(links: np.ndarray) -> np.ndarray:
    """``(k,)`` int64 component of each node: nodes joined by a chain of direct links share one.

    Components are numbered by their lowest node, in increasing order.
    """
    return components(np.ascontiguousarray(links, dtype=np.bool_))
