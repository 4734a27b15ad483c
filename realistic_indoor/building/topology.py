"""The building's topology as a networkx graph."""

from __future__ import annotations

from typing import TYPE_CHECKING

import networkx as nx

from realistic_indoor.building.labels import CIRCULATION_LABELS, OUTSIDE

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = ["building_graph", "circulation_loops"]


def building_graph(building: Building, include_outside: bool = False) -> nx.MultiGraph:
    """Build the room graph of ``building`` (see :meth:`Building.graph`)."""
    g = nx.MultiGraph()
    for r in building.rooms:
        g.add_node(r.id, label=r.label, function=r.function, area=r.area)
    if include_outside:
        g.add_node(OUTSIDE, label=None, function=OUTSIDE, area=0.0)
    for d in building.doors:
        if d.room_b is None:
            if include_outside:
                g.add_edge(d.room_a, OUTSIDE, key=d.id, width_m=d.width_m)
        else:
            g.add_edge(d.room_a, d.room_b, key=d.id, width_m=d.width_m)
    return g


def circulation_loops(building: Building) -> int:
    """Independent loops of the corridors and halls: the cycle rank of their door graph.

    Doors between two circulation rooms are counted once per pair (a wide opening and a door
    between the same two corridors make no loop). 0 for a tree of corridors; 1 for a ring.
    """
    ids = [r.id for r in building.rooms if r.label in CIRCULATION_LABELS]
    graph = nx.Graph(building.graph().subgraph(ids))
    if graph.number_of_nodes() == 0:
        return 0
    return graph.number_of_edges() - graph.number_of_nodes() + nx.number_connected_components(graph)
