"""Suites: medium and big rooms entered only through a neighbour, as real plans have them."""

from __future__ import annotations

from typing import TYPE_CHECKING

from realistic_indoor.generator.doors import RULES, door_fits
from realistic_indoor.generator.plan import B, M

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.plan import Plan

__all__ = ["make_suites"]


def make_suites(plan: Plan, rng: np.random.Generator, share: float) -> None:
    """Make about ``share`` of the medium and big rooms inner rooms of a neighbour (a suite).

    An inner room's only door leads into its host, a medium or big room that keeps its own door
    to the corridor (an office with a meeting room behind it, a manager's office behind a
    secretary's). Real plans have such rooms; a generator that gives every room its own
    corridor door has too many rooms with two doors and too few reached through another room.
    """
    rooms = [i for i, r in enumerate(plan.rooms) if r.label in (M, B) and r.role == "room" and r.host < 0]
    ordinary = set(rooms)
    want = int(share * len(rooms) + rng.random())
    neighbours = plan.neighbours()
    hosts: set[int] = set()
    for k in rng.permutation(len(rooms)):
        if want <= 0:
            break
        j = rooms[int(k)]
        if j in hosts:
            continue
        mates = [
            i
            for i in neighbours[j]
            if i in ordinary and i not in hosts and plan.rooms[i].host < 0 and _door_wall(plan, i, j)
        ]
        if mates:
            host = mates[int(rng.integers(len(mates)))]
            plan.rooms[j].host, plan.rooms[j].role = host, "back"
            hosts.add(host)
            want -= 1


def _door_wall(plan: Plan, i: int, j: int) -> bool:
    """Whether rooms ``i`` and ``j`` share a wall a room door fits in."""
    return any(door_fits(w, RULES.room) for w in plan.shared(i, j))
