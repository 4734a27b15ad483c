"""How many units of each kind a building's strips should hold to match the model's shares."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import area_to_units
from realistic_indoor.generator.plan import B, M, S
from realistic_indoor.generator.rooms.bays import MIN_SMALL, Budget, core_shape

if TYPE_CHECKING:
    from realistic_indoor.generator.rooms.regions import FloorRegions
    from realistic_indoor.models.building_model import BuildingTypeModel

__all__ = ["building_budget"]


@dataclass(frozen=True)
class _Frontage:
    """What the strips offer and what units need of it (units)."""

    deep_length: float
    deep_depth: float
    shallow_length: float
    shallow_depth: float
    core_width: float
    rooms_per_core: float
    ends: int
    placed_small: float = 0.0


def _frontage(
    regions: FloorRegions,
    model: BuildingTypeModel,
    stub: int,
    core_rows: tuple[int, int],
    limit: int,
    placed_small: float,
) -> _Frontage:
    deep = [b for b in regions.bays if b.depth >= limit]
    shallow = [b for b in regions.bays if b.depth < limit]
    length = sum(b.length for b in deep)
    depth = sum(b.depth * b.length for b in deep) / max(length, 1)
    s_length = sum(b.length for b in shallow)
    s_depth = sum(b.depth * b.length for b in shallow) / max(s_length, 1)
    rows, side, per_core = core_shape(model, round(depth), core_rows)
    core_width = stub + 2 * side if per_core == 2 * rows else side * per_core
    return _Frontage(
        length,
        max(depth, 1),
        s_length,
        max(s_depth, 1),
        core_width,
        per_core,
        len(regions.ends),
        placed_small,
    )


def _units_for(n: float, f: _Frontage, model: BuildingTypeModel) -> dict[str, float]:
    """Units for ``n`` ordinary rooms in all, following the model's shares and structures."""
    p = model.shares()
    total = max(p[S] + p[M] + p[B], 1e-6)
    ps, pm, pb = p[S] / total, p[M] / total, p[B] / total
    st = model.structures
    w_small = max(area_to_units(model.stats(S).area_mean) / f.shallow_depth, MIN_SMALL)
    need_s = ps * n
    closets = st.closets_per_room * (pm + pb) * n
    rest = need_s * (1 - st.clustered_small_rooms) - closets - f.ends - f.placed_small
    small = min(max(rest, 0.0), f.shallow_length / w_small)
    shallow_m = max(f.shallow_length - small * w_small, 0.0) / (
        area_to_units(model.stats(M).area_mean) / f.shallow_depth
    )
    notches = max(rest - small, 0.0)
    closets = max(closets + min(rest, 0.0), 0.0)
    paired = closets + notches
    return {
        "M": pm * n - shallow_m - 0.75 * paired,
        "B": pb * n - 0.25 * paired,
        "closet": closets,
        "notch": notches,
        "core": st.clustered_small_rooms * need_s / f.rooms_per_core,
        "S": small,
        "shallow_m": shallow_m,
    }


def _deep_frontage(units: dict[str, float], f: _Frontage, model: BuildingTypeModel) -> float:
    """Length of deep strip the units take (closets and notches go with medium and big rooms)."""
    paired = units["closet"] + units["notch"]
    medium = area_to_units((max(units["M"], 0) + 0.75 * paired) * model.stats(M).area_mean) / f.deep_depth
    big = area_to_units((max(units["B"], 0) + 0.25 * paired) * model.stats(B).area_mean) / f.deep_depth
    notch = units["notch"] * max(math.sqrt(area_to_units(model.stats(S).area_mean)), MIN_SMALL)
    return medium + big + units["core"] * f.core_width + notch


def building_budget(
    regions: FloorRegions,
    model: BuildingTypeModel,
    stub: int,
    core_rows: tuple[int, int],
    limit: int,
    placed_small: float = 0.0,
) -> Budget:
    """Units the strips should hold so that the building matches the model's label shares.

    Small rooms come from corridor ends, closets, service cores (the model's clustered share),
    shallow strips and, for the rest, notches beside rooms; shallow strips take medium rooms
    once the small ones are enough. The number of ordinary rooms is the one whose units fill
    the deep strips (found by bisection: the frontage grows with it).

    Args:
        regions: The painted strips and end rooms.
        model: Shares, areas and structure frequencies.
        stub: Width of a service core's corridor (units).
        core_rows: Range of small rooms per side of a core.
        limit: Strips shallower than this hold small rooms (units).
        placed_small: Small rooms the building gets outside the strips (an annex's service
            rooms), counted against the model's share.
    """
    f = _frontage(regions, model, stub, core_rows, limit, placed_small)
    lo, hi = 0.0, 1.0
    while _deep_frontage(_units_for(hi, f, model), f, model) < f.deep_length and hi < 1e6:
        hi *= 2
    for _ in range(40):
        mid = (lo + hi) / 2
        lo, hi = (
            (mid, hi) if _deep_frontage(_units_for(mid, f, model), f, model) < f.deep_length else (lo, mid)
        )
    want = _units_for(lo, f, model)
    want["M"] += want.pop("shallow_m")
    return Budget(want)
