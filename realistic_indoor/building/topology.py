"""The building's topology as a networkx graph."""

from __future__ import annotations

from typing import TYPE_CHECKING

import networkx as nx

from realistic_indoor.building.labels import OUTSIDE

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = ["building_graph"]


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
