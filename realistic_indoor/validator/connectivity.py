"""Connectivity facts of a building's topology, as the paper measures them.

Every function takes one :class:`~realistic_indoor.building.Building`; :func:`connectivity`
gathers them into a :class:`Connectivity` record whose counts add up over a set of buildings
(:meth:`Connectivity.combine`), so set-level shares are pooled over rooms as in the paper.

Definitions (doors are counted as the plan gives them; an exterior door leads to "outside"):

- *core rooms*: rooms whose functional label is the building type's core function
  (:data:`~realistic_indoor.building.labels.CORE_FUNCTIONS`: offices in offices, classrooms in schools, bedrooms in houses).
- a room *touches a corridor* when at least one of its doors leads to a corridor.
- *ordinary rooms*: small, medium and big rooms (not corridors or halls).
- an ordinary room is *connected only to corridors* when it has at least one door and every
  door (exterior ones included) leads to a corridor.
- the same two with halls counted as corridors (*circulation*: corridors and halls) are
  reported beside them: in the shared real offices 80% of offices touch a corridor and 97%
  touch a corridor or a hall (the paper: 98%).
- a *dead-end corridor* has exactly one doorway.
- a corridor is *connected only to corridors* when it has a door and all its doors lead to
  corridors.
- a *room maze*: a connected component of the subgraph of ordinary rooms (corridors, halls and
  the outside removed) with at least :data:`MAZE_MIN_ROOMS` rooms of which at most one touches a
  corridor, a hall or the outside. All the other rooms of a maze are reachable only through
  each other.
- an ordinary room is *indirect* when none of its doors leads to a corridor, a hall or outside.
- path lengths count doors between two rooms (all labels) along the shortest path; pairs in
  different connected parts are left out.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import TYPE_CHECKING

import networkx as nx
import numpy as np

from realistic_indoor.building.labels import (
    CIRCULATION_LABELS,
    ROOM_LABELS,
    SemanticLabel,
    is_core_function,
)

if TYPE_CHECKING:
    from collections.abc import Collection, Iterable, Sequence

    from realistic_indoor.building.building import Building

__all__ = [
    "CONNECTIVITY_METRICS",
    "MAZE_MIN_ROOMS",
    "Connectivity",
    "ConnectivityMetric",
    "connectivity",
    "core_rooms",
    "corridors_only_to_corridors",
    "dead_end_corridors",
    "indirect_rooms",
    "path_lengths",
    "room_mazes",
    "rooms_only_to_corridors",
    "rooms_touching_corridor",
    "set_connectivity",
]

MAZE_MIN_ROOMS = 3
"""Fewest ordinary rooms reachable only through each other that make a room maze."""


def _neighbour_labels(b: Building, room_id: str) -> list[SemanticLabel | None]:
    """Label of the room behind each door of ``room_id`` (``None`` for outside or unknown)."""
    out: list[SemanticLabel | None] = []
    for d in b.doors_of[room_id]:
        other = d.other(room_id)
        out.append(b.room(other).label if other in b.room_by_id else None)
    return out


def core_rooms(b: Building) -> list[str]:
    """Ids of the rooms whose function is the building type's core function."""
    return [r.id for r in b.rooms if is_core_function(r.function, b.building_type)]


def rooms_touching_corridor(
    b: Building, room_ids: Iterable[str], via: Collection[SemanticLabel] = (SemanticLabel.CORRIDOR,)
) -> list[str]:
    """The rooms among ``room_ids`` with at least one door to a corridor (or to a room of ``via``)."""
    return [rid for rid in room_ids if any(lab in via for lab in _neighbour_labels(b, rid))]


def _ordinary_rooms(b: Building) -> list[str]:
    return [r.id for r in b.rooms if r.label in ROOM_LABELS]


def rooms_only_to_corridors(
    b: Building, via: Collection[SemanticLabel] = (SemanticLabel.CORRIDOR,)
) -> list[str]:
    """Ordinary rooms with at least one door, every door leading to a corridor (or a room of ``via``)."""
    out = []
    for rid in _ordinary_rooms(b):
        labels = _neighbour_labels(b, rid)
        if labels and all(lab in via for lab in labels):
            out.append(rid)
    return out


def _corridors(b: Building) -> list[str]:
    return [r.id for r in b.rooms if r.label is SemanticLabel.CORRIDOR]


def dead_end_corridors(b: Building) -> list[str]:
    """Corridors with exactly one doorway."""
    return [rid for rid in _corridors(b) if len(b.doors_of[rid]) == 1]


def corridors_only_to_corridors(b: Building) -> list[str]:
    """Corridors with at least one door, every door leading to another corridor."""
    out = []
    for rid in _corridors(b):
        labels = _neighbour_labels(b, rid)
        if labels and all(lab is SemanticLabel.CORRIDOR for lab in labels):
            out.append(rid)
    return out


def _is_gateway(b: Building, room_id: str) -> bool:
    """Whether a room has a door to a corridor, a hall or outside."""
    return any(lab is None or lab in CIRCULATION_LABELS for lab in _neighbour_labels(b, room_id))


def indirect_rooms(b: Building) -> list[str]:
    """Ordinary rooms with no door to a corridor, a hall or outside (reached through rooms only)."""
    return [rid for rid in _ordinary_rooms(b) if not _is_gateway(b, rid)]


def room_mazes(b: Building, min_rooms: int = MAZE_MIN_ROOMS) -> list[frozenset[str]]:
    """Groups of ordinary rooms reachable only through each other.

    A maze is a connected component of the topology restricted to small, medium and big rooms
    that holds at least ``min_rooms`` rooms, at most one of which has a door to a corridor, a
    hall or outside.

    Args:
        b: The building.
        min_rooms: Smallest component that counts as a maze.

    Returns:
        The mazes as sets of room ids, largest first (ties in room order).
    """
    ordinary = _ordinary_rooms(b)
    sub = nx.Graph()
    sub.add_nodes_from(ordinary)
    sub.add_edges_from((d.room_a, d.room_b) for d in b.doors if d.room_a in sub and d.room_b in sub)
    order = {rid: i for i, rid in enumerate(ordinary)}
    mazes = [
        frozenset(comp)
        for comp in nx.connected_components(sub)
        if len(comp) >= min_rooms and sum(_is_gateway(b, rid) for rid in comp) <= 1
    ]
    return sorted(mazes, key=lambda m: (-len(m), min(order[r] for r in m)))


def path_lengths(b: Building) -> tuple[float, int]:
    """Mean and longest shortest path between two rooms, in doors.

    Returns:
        ``(mean, longest)`` over all pairs of rooms joined by some path; ``(nan, 0)`` when no
        two rooms are joined.
    """
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import shortest_path

    index = {r.id: i for i, r in enumerate(b.rooms)}
    pairs = [(index[d.room_a], index[d.room_b]) for d in b.doors if d.room_a in index and d.room_b in index]
    if not pairs:
        return float("nan"), 0
    rows, cols = np.asarray(pairs).T
    adj = coo_matrix((np.ones(len(pairs)), (rows, cols)), shape=(len(index), len(index))).tocsr()
    dist = shortest_path(adj, directed=False, unweighted=True)
    upper = dist[np.triu_indices(len(index), k=1)]
    finite = upper[np.isfinite(upper)]
    if not len(finite):
        return float("nan"), 0
    return float(finite.mean()), int(finite.max())


@dataclass(frozen=True)
class ConnectivityMetric:
    """One reported connectivity share or length.

    Attributes:
        key: Name of the :class:`Connectivity` property.
        title: Short column title.
        phrase: Words that follow the value in a sentence (``"42% of offices touch a corridor"``).
        unit: ``"%"`` or ``"doors"``.
    """

    key: str
    title: str
    phrase: str
    unit: str


CONNECTIVITY_METRICS: tuple[ConnectivityMetric, ...] = (
    ConnectivityMetric(
        "core_touching_corridor_pct", "core rooms touching a corridor", "of core rooms touch a corridor", "%"
    ),
    ConnectivityMetric(
        "core_touching_circulation_pct",
        "core rooms touching a corridor or hall",
        "of core rooms touch a corridor or a hall",
        "%",
    ),
    ConnectivityMetric(
        "only_to_corridors_pct",
        "rooms connected only to corridors",
        "of small/medium/big rooms connect only to corridors",
        "%",
    ),
    ConnectivityMetric(
        "only_to_circulation_pct",
        "rooms connected only to corridors/halls",
        "of small/medium/big rooms connect only to corridors and halls",
        "%",
    ),
    ConnectivityMetric(
        "indirect_rooms_pct",
        "rooms reached only through rooms",
        "of small/medium/big rooms are reached only through other rooms",
        "%",
    ),
    ConnectivityMetric(
        "maze_rooms_pct", "rooms in room mazes", "of small/medium/big rooms are in room mazes", "%"
    ),
    ConnectivityMetric("dead_end_corridors_pct", "dead-end corridors", "of corridors are dead ends", "%"),
    ConnectivityMetric(
        "corridor_only_corridors_pct",
        "corridors joining only corridors",
        "of corridors connect only to corridors",
        "%",
    ),
    ConnectivityMetric(
        "mean_path_doors",
        "mean path between rooms (doors)",
        "doors on the mean path between two rooms",
        "doors",
    ),
    ConnectivityMetric(
        "longest_path_doors",
        "longest path between rooms (doors)",
        "doors on the longest shortest path between two rooms",
        "doors",
    ),
)
"""The metrics a report shows, in order."""


def _pct(part: int, whole: int) -> float:
    return 100.0 * part / whole if whole else float("nan")


@dataclass(frozen=True)
class Connectivity:
    """Connectivity counts of one building or, pooled, of a set of buildings.

    Counts add up over buildings; path lengths are averaged over the buildings that have any.

    Attributes:
        buildings: Number of buildings.
        core_rooms: Rooms with the type's core function.
        core_touching_corridor: Core rooms with a door to a corridor.
        core_touching_circulation: Core rooms with a door to a corridor or a hall.
        ordinary_rooms: Small, medium and big rooms.
        only_to_corridors: Ordinary rooms all of whose doors lead to corridors.
        only_to_circulation: Ordinary rooms all of whose doors lead to corridors or halls.
        indirect_rooms: Ordinary rooms with no door to a corridor, hall or outside.
        mazes: Room mazes.
        maze_rooms: Rooms in room mazes.
        corridors: Corridors.
        dead_end_corridors: Corridors with one doorway.
        corridor_only_corridors: Corridors whose doors all lead to corridors.
        path_buildings: Buildings with at least two rooms joined by a door.
        mean_path_doors: Mean over those buildings of the mean shortest path between rooms, doors.
        longest_path_doors: Mean over those buildings of the longest shortest path, doors.
        max_path_doors: Longest shortest path in any of the buildings, doors.
    """

    buildings: int
    core_rooms: int
    core_touching_corridor: int
    core_touching_circulation: int
    ordinary_rooms: int
    only_to_corridors: int
    only_to_circulation: int
    indirect_rooms: int
    mazes: int
    maze_rooms: int
    corridors: int
    dead_end_corridors: int
    corridor_only_corridors: int
    path_buildings: int
    mean_path_doors: float
    longest_path_doors: float
    max_path_doors: int

    @property
    def core_touching_corridor_pct(self) -> float:
        """Share of core rooms that touch a corridor, % (NaN without core rooms)."""
        return _pct(self.core_touching_corridor, self.core_rooms)

    @property
    def core_touching_circulation_pct(self) -> float:
        """Share of core rooms that touch a corridor or a hall, %."""
        return _pct(self.core_touching_circulation, self.core_rooms)

    @property
    def only_to_circulation_pct(self) -> float:
        """Share of ordinary rooms connected only to corridors and halls, %."""
        return _pct(self.only_to_circulation, self.ordinary_rooms)

    @property
    def only_to_corridors_pct(self) -> float:
        """Share of ordinary rooms connected only to corridors, %."""
        return _pct(self.only_to_corridors, self.ordinary_rooms)

    @property
    def indirect_rooms_pct(self) -> float:
        """Share of ordinary rooms reached only through other rooms, %."""
        return _pct(self.indirect_rooms, self.ordinary_rooms)

    @property
    def maze_rooms_pct(self) -> float:
        """Share of ordinary rooms that are in a room maze, %."""
        return _pct(self.maze_rooms, self.ordinary_rooms)

    @property
    def dead_end_corridors_pct(self) -> float:
        """Share of corridors that are dead ends, % (NaN without corridors)."""
        return _pct(self.dead_end_corridors, self.corridors)

    @property
    def corridor_only_corridors_pct(self) -> float:
        """Share of corridors connected only to corridors, %."""
        return _pct(self.corridor_only_corridors, self.corridors)

    def metrics(self) -> dict[str, float]:
        """Every metric of :data:`CONNECTIVITY_METRICS`, keyed by name."""
        return {m.key: float(getattr(self, m.key)) for m in CONNECTIVITY_METRICS}

    def to_dict(self) -> dict[str, float]:
        """Counts and metrics as plain data."""
        return {**{f.name: getattr(self, f.name) for f in fields(self)}, **self.metrics()}

    @classmethod
    def combine(cls, parts: Sequence[Connectivity]) -> Connectivity:
        """Pool the counts of several buildings (path lengths averaged per building)."""
        total: dict[str, float] = {f.name: sum(getattr(p, f.name) for p in parts) for f in fields(cls)}
        with_paths = [p for p in parts if p.path_buildings]
        n = sum(p.path_buildings for p in with_paths)
        for key in ("mean_path_doors", "longest_path_doors"):
            total[key] = sum(getattr(p, key) * p.path_buildings for p in with_paths) / n if n else math.nan
        total["max_path_doors"] = max((p.max_path_doors for p in parts), default=0)
        return cls(**total)


def connectivity(b: Building) -> Connectivity:
    """Every connectivity count of one building (see the module docstring for definitions)."""
    core = core_rooms(b)
    corridors = _corridors(b)
    mazes = room_mazes(b)
    mean_path, longest = path_lengths(b)
    has_paths = not math.isnan(mean_path)
    return Connectivity(
        buildings=1,
        core_rooms=len(core),
        core_touching_corridor=len(rooms_touching_corridor(b, core)),
        core_touching_circulation=len(rooms_touching_corridor(b, core, CIRCULATION_LABELS)),
        ordinary_rooms=len(_ordinary_rooms(b)),
        only_to_corridors=len(rooms_only_to_corridors(b)),
        only_to_circulation=len(rooms_only_to_corridors(b, CIRCULATION_LABELS)),
        indirect_rooms=len(indirect_rooms(b)),
        mazes=len(mazes),
        maze_rooms=sum(len(m) for m in mazes),
        corridors=len(corridors),
        dead_end_corridors=len(dead_end_corridors(b)),
        corridor_only_corridors=len(corridors_only_to_corridors(b)),
        path_buildings=int(has_paths),
        mean_path_doors=mean_path,
        longest_path_doors=float(longest) if has_paths else math.nan,
        max_path_doors=longest,
    )


def set_connectivity(buildings: Iterable[Building]) -> Connectivity:
    """Connectivity of a set of buildings, pooled (see :meth:`Connectivity.combine`)."""
    return Connectivity.combine([connectivity(b) for b in buildings])
