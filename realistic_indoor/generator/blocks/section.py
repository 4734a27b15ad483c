"""A block's plan, drawn once: bars across its depth, crossings, halls, courts and steps.

A block is a rectangle cut across its depth into *bars*, each a corridor with a strip of rooms
on both sides; neighbouring bars stand back to back, so the strips between two corridors form
a *core*. One bar is a double-loaded corridor; two or more are a ring ("racetrack") around
cores: two corridors cross the block near its ends, with a strip of rooms between each and the
end facade, and longer blocks get more crossings through the cores. Everything along the
block's length is kept as a fraction of it, so the same section paints any length
(:func:`realistic_indoor.generator.blocks.paint.paint_block`), and the length can be solved for
the floor area.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from realistic_indoor.generator.geometry import to_units

if TYPE_CHECKING:
    import numpy as np

    from realistic_indoor.generator.blocks.style import BlockStyle
    from realistic_indoor.generator.rooms.dims import Dims

__all__ = ["Hall", "Section", "draw_section", "mean_block_depth"]

MIN_STRIP_M = 3.0
"""Shallowest strip of rooms a step may leave (m)."""

MIN_CORE_SCALE = 0.8
"""Shallowest core strip, as a share of the type's strip depth, that slimming a block leaves."""


@dataclass(frozen=True)
class Hall:
    """A hall cut into the block.

    Attributes:
        where: ``"S"`` or ``"N"``: in that facade strip, reaching from the facade to the
            corridor; an integer ``j``: across core ``j``, joining corridors ``j`` and ``j + 1``.
        at: Position of its middle along the block (fraction of the inner run).
        area: Floor area wanted (square units).
        through: Across a core: whether the hall reaches both corridors (else it takes the
            core's strip on the side of ``half`` and opens onto that corridor only).
        half: ``"lo"`` or ``"hi"``: the core's strip a hall that is not ``through`` takes.
    """

    where: str | int
    at: float
    area: int
    through: bool = True
    half: str = "lo"


@dataclass(frozen=True)
class Section:
    """A block's plan with the length left open (grid units, fractions along the length).

    Attributes:
        depths: ``(south strip, north strip)`` of each bar, from south to north.
        corridor: Corridor width.
        end_depth: Depth of the strips between the crossing corridors and the end facades
            (0 for a single bar, whose corridor runs to both ends).
        crossings: Fractions of the inner run where corridors cross the cores.
        halls: The halls.
        courts: ``(core, section)``: the section-th stretch of core ``core`` between
            crossings is a courtyard.
        steps: ``(side, f0, f1, depth)``: the facade strip on ``side`` (``"S"``/``"N"``) is
            ``depth`` shallower from fraction ``f0`` to ``f1`` of its length.
        deep: ``(core, section, side)``: the section-th stretch of core ``core`` between
            crossings is one strip as deep as the core, its rooms opening onto the corridor on
            ``side`` (``"S"`` or ``"N"``): where real offices put open-plan rooms and meeting
            rooms, as deep as they are wide.
    """

    depths: tuple[tuple[int, int], ...]
    corridor: int
    end_depth: int
    crossings: tuple[float, ...]
    halls: tuple[Hall, ...]
    courts: tuple[tuple[int, int], ...]
    steps: tuple[tuple[str, float, float, int], ...]
    deep: tuple[tuple[int, int, str], ...] = ()

    @property
    def depth(self) -> int:
        """The block's depth (units)."""
        return sum(s + n + self.corridor for s, n in self.depths)

    @property
    def bars(self) -> int:
        """Number of corridors along the block."""
        return len(self.depths)

    def run(self, length: int) -> tuple[int, int]:
        """Start and end of the long corridors along a block of ``length`` (units)."""
        if self.bars == 1:
            return 0, length
        return self.end_depth + self.corridor, length - self.end_depth - self.corridor


def draw_section(
    rng: np.random.Generator,
    area: int,
    dims: Dims,
    style: BlockStyle,
    n_halls: int,
    hall_area: float,
    bars: int | None = None,
    aspect: float | None = None,
) -> tuple[Section, int]:
    """Draw a block's plan for a floor area; returns it and the length it is first tried at.

    The block's depth holds as many bars as make its proportions the aspect ratio, or ``bars``
    if given (the wings of a composed footprint have one). A block of two or more bars that
    comes out squarer than the aspect ratio has its core strips made shallower, down to
    :data:`MIN_CORE_SCALE` of a facade strip, so a small office can be a slim ring rather
    than a square one.

    Args:
        rng: Random generator.
        area: Floor area wanted (square units).
        dims: Corridor width and strip depths.
        style: The type's block conventions.
        n_halls: Halls wanted, the entrance lobby first.
        hall_area: Mean hall area (square units).
        bars: The number of bars, or ``None`` to choose it from the aspect ratio.
        aspect: The footprint's length over its depth wanted (the building-type model's draw),
            or ``None`` to draw it from the style's range.
    """
    # drawn even where ``aspect`` is given, so the rest of the section takes the same draws
    drawn = math.exp(rng.uniform(*(math.log(a) for a in style.aspect)))
    aspect = drawn if aspect is None else aspect
    k = _bars_for(area, aspect, dims, style) if bars is None else bars
    depths = _slim_cores(_bar_depths(rng, k, dims.depth, style), area, aspect, dims)
    corridor = dims.corridor
    depth = sum(s + n + corridor for s, n in depths)
    length = max(round(area / depth), 2 * corridor)
    end = round(dims.depth * rng.uniform(0.9, 1.1)) if k > 1 else 0
    inner = max(length - 2 * (end + corridor), 1)
    crossings = _crossings(rng, k, inner, style)
    halls = _halls(rng, k, n_halls, hall_area, style)
    courts = _courts(rng, k, len(crossings) + 1, inner, style, depths, corridor)
    steps = _steps(rng, depths, style)
    deep = _deep_cores(rng, k, len(crossings) + 1, style, courts)
    return Section(tuple(depths), corridor, end, crossings, halls, courts, steps, deep), length


def mean_block_depth(dims: Dims, style: BlockStyle, bars: int) -> float:
    """Mean depth of a block of ``bars`` bars (units).

    Two facade strips, ``2 (bars - 1)`` core strips and ``bars`` corridors, at the middle of the
    style's ranges of strip depth.
    """
    facade = dims.depth * sum(style.facade_scale) / 2
    core = dims.depth * sum(style.core_scale) / 2
    return 2 * facade + 2 * (bars - 1) * core + bars * dims.corridor


def _bars_for(area: int, aspect: float, dims: Dims, style: BlockStyle) -> int:
    """The number of bars whose block, at the area, comes nearest the aspect ratio.

    A block of ``k`` bars is :func:`mean_block_depth` deep; its length is the area over that
    depth.
    """
    facade = dims.depth * sum(style.facade_scale) / 2

    def miss(k: int) -> float:
        depth = mean_block_depth(dims, style, k)
        length = area / depth
        if k > 1 and length < 2 * facade + 2 * dims.corridor + to_units(8.0):
            return math.inf
        return abs(abs(math.log(length / depth)) - math.log(aspect))

    return min(range(1, 40), key=miss)


def _slim_cores(depths: list[tuple[int, int]], area: int, aspect: float, dims: Dims) -> list[tuple[int, int]]:
    """The bars' strip depths, the core strips made shallower where the block is squarer than ``aspect``.

    The block's depth is brought towards ``sqrt(area / aspect)`` by scaling every core strip
    alike, none below ``MIN_CORE_SCALE`` of the type's strip depth; facade strips keep theirs.
    """
    if len(depths) < 2:
        return depths
    corridors = len(depths) * dims.corridor
    facades = depths[0][0] + depths[-1][1]
    cores = sum(s + n for s, n in depths) - facades
    depth = corridors + facades + cores
    if cores <= 0 or area / depth >= aspect * depth:
        return depths
    floor = round(MIN_CORE_SCALE * dims.depth)
    scale = max((math.sqrt(area / aspect) - corridors - facades) / cores, 0.0)

    def slim(d: int) -> int:
        return max(min(round(d * scale), d), min(floor, d))

    last = len(depths) - 1
    return [(s if j == 0 else slim(s), n if j == last else slim(n)) for j, (s, n) in enumerate(depths)]


def _bar_depths(rng: np.random.Generator, k: int, depth: int, style: BlockStyle) -> list[tuple[int, int]]:
    """Strip depths of each bar: facade strips about ``depth``, core strips scaled by the style."""

    def facade() -> int:
        return round(depth * rng.uniform(*style.facade_scale))

    def core() -> int:
        return round(depth * rng.uniform(*style.core_scale))

    if k == 1:
        return [(facade(), facade())]
    return [(facade() if j == 0 else core(), facade() if j == k - 1 else core()) for j in range(k)]


def _crossings(rng: np.random.Generator, k: int, inner: int, style: BlockStyle) -> tuple[float, ...]:
    """Fractions of the inner run where corridors cross the cores, about a section apart."""
    if k == 1:
        return ()
    n = max(1, round(inner / to_units(rng.uniform(*style.section_m)))) - 1
    return tuple((i + 1) / (n + 1) + rng.uniform(-0.15, 0.15) / (n + 1) for i in range(n))


def _halls(rng: np.random.Generator, k: int, n: int, area: float, style: BlockStyle) -> tuple[Hall, ...]:
    """The lobby on the south facade, then halls across cores or on a facade strip."""
    halls = [Hall("S", rng.uniform(0.3, 0.7), round(area * style.hall_area_scale * rng.uniform(0.8, 1.3)))]
    for _ in range(max(n, 1) - 1):
        if k > 1 and rng.random() < style.core_hall_p:
            where: str | int = int(rng.integers(k - 1))
        else:
            where = "SN"[int(rng.integers(2))]
        size = round(area * style.hall_area_scale * math.exp(rng.normal(0.0, 0.35)))
        through = bool(rng.random() < style.through_hall_p)
        half = "lo" if rng.random() < 0.5 else "hi"
        halls.append(Hall(where, float(rng.uniform(0.05, 0.95)), size, through, half))
    return tuple(halls)


def _courts(
    rng: np.random.Generator,
    k: int,
    sections: int,
    inner: int,
    style: BlockStyle,
    depths: list[tuple[int, int]],
    corridor: int,
) -> tuple[tuple[int, int], ...]:
    """Core sections that become courtyards (never all of them: the rooms need the rest)."""
    if k == 1 or style.court_p <= 0:
        return ()
    if min(inner / sections, depths[0][1] + depths[1][0]) < to_units(9.0) + 2 * corridor:
        return ()
    pairs = [(j, i) for j in range(k - 1) for i in range(sections) if rng.random() < style.court_p]
    return tuple(pairs[: max(0, (k - 1) * sections - 1)])


def _deep_cores(
    rng: np.random.Generator, k: int, sections: int, style: BlockStyle, courts: tuple[tuple[int, int], ...]
) -> tuple[tuple[int, int, str], ...]:
    """Core sections (not courtyards) that are one deep strip of rooms, and the side they open onto."""
    if k == 1 or style.deep_core_p <= 0:
        return ()
    out = []
    for j in range(k - 1):
        for i in range(sections):
            side = "S" if rng.random() < 0.5 else "N"
            if rng.random() < style.deep_core_p and (j, i) not in courts:
                out.append((j, i, side))
    return tuple(out)


def _steps(
    rng: np.random.Generator, depths: list[tuple[int, int]], style: BlockStyle
) -> tuple[tuple[str, float, float, int], ...]:
    """Facade strips stepped back over one end or the middle of their length, or left out at an end.

    A step as deep as its strip leaves that stretch of the strip out (a notch in the footprint).
    """
    out = []
    for side, strip in (("S", depths[0][0]), ("N", depths[-1][1])):
        if rng.random() < style.notch_p:
            f = float(rng.uniform(0.2, 0.45))
            out.append((side, 0.0, f, strip) if rng.random() < 0.5 else (side, 1.0 - f, 1.0, strip))
            continue
        room = strip - to_units(MIN_STRIP_M)
        if room < to_units(1.0) or rng.random() >= style.step_p:
            continue
        step = min(to_units(rng.uniform(*style.step_m)), room)
        f0, f1 = sorted(rng.uniform(0.0, 1.0, 2))
        f0, f1 = (0.0, f1) if f0 < 0.3 else (f0, 1.0) if f1 > 0.7 else (f0, f1)
        if f1 - f0 > 0.15:
            out.append((side, float(f0), float(f1), step))
    return tuple(out)
