"""The block layout: compact footprints, strips that tile the block, the options that choose it."""

from dataclasses import replace

import numpy as np
import pytest
from shapely.geometry import box
from shapely.ops import unary_union

from realistic_indoor.errors import ConfigError
from realistic_indoor.generator import make_generator
from realistic_indoor.generator.blocks import OFFICE_BLOCKS, SCHOOL_BLOCKS
from realistic_indoor.generator.blocks.paint import paint_block
from realistic_indoor.generator.blocks.section import Hall, Section, draw_section
from realistic_indoor.generator.rooms.dims import Dims
from realistic_indoor.generator.typed import OfficeGenerator
from realistic_indoor.validator.building_measures import building_measures


def _rects(regions):
    return regions.corridors + [r for _, rs in regions.halls for r in rs] + [b.rect for b in regions.bays]


def test_paint__a_single_bar_is_a_corridor_between_two_strips():
    # 60 m long, strips 6 m and 5 m deep, corridor 2 m: 13 m deep, 780 m2, corridor 120 m2
    s = Section(((60, 50),), 20, 0, (), (), (), ())
    r = paint_block(s, 600)
    assert r.corridors == [(0, 60, 600, 80)]
    assert sorted(b.rect for b in r.bays) == [(0, 0, 600, 60), (0, 80, 600, 130)]
    assert r.area == 600 * 130


def test_paint__two_bars_make_a_ring_around_a_core():
    # bars (6, 7) and (7, 6) m, corridor 2 m: 30 m deep; 50 m long with 6 m end strips
    s = Section(((60, 70), (70, 60)), 20, 60, (), (), (), ())
    r = paint_block(s, 500)
    assert (60, 60, 440, 80) in r.corridors and (60, 220, 440, 240) in r.corridors
    assert (60, 80, 80, 220) in r.corridors and (420, 80, 440, 220) in r.corridors
    union = unary_union([box(*x) for x in _rects(r)])
    assert union.area == pytest.approx(500 * 300)
    assert union.geom_type == "Polygon" and not union.interiors


def test_paint__a_hall_across_the_core_joins_both_corridors():
    s = Section(((60, 70), (70, 60)), 20, 60, (), (Hall(0, 0.5, 100 * 140),), (), ())
    r = paint_block(s, 500)
    [(_, [hall])] = r.halls
    assert hall[1] == 80 and hall[3] == 220  # from corridor 0's side to corridor 1's
    assert hall[2] - hall[0] == 100  # 140 m2 over a 14 m deep core: 10 m wide


def test_paint__a_deep_core_section_is_one_strip_opening_onto_one_corridor():
    # the ring above with one crossing at the middle of the inner run (8..42 m: at 25 m, 2 m
    # wide, 24..26 m); the west section (8..24 m) is one strip as deep as the core (14 m)
    s = Section(((60, 70), (70, 60)), 20, 60, (0.5,), (), (), (), ((0, 0, "N"),))
    r = paint_block(s, 500)
    deep = [b for b in r.bays if b.rect[1] == 80 and b.rect[3] == 220]
    assert [(b.rect, b.access) for b in deep] == [((80, 80, 240, 220), "N")]
    core = [b.rect for b in r.bays if b.rect[1] >= 80 and b.rect[3] <= 220]
    assert sorted(core) == [(80, 80, 240, 220), (260, 80, 420, 150), (260, 150, 420, 220)]
    union = unary_union([box(*x) for x in _rects(r)])
    assert union.area == pytest.approx(500 * 300)


def _deepest_big_and_rooms(monkeypatch, deep_core_p: float) -> list[tuple[str, float, int]]:
    """Per seed: the footprint's shape, the big room with the longest short side (m), the rooms."""
    monkeypatch.setattr(OfficeGenerator, "blocks", replace(OFFICE_BLOCKS, deep_core_p=deep_core_p))
    gen = make_generator("office", area_m2=2200.0)
    out = []
    for seed in range(12):
        b = gen(np.random.default_rng(seed))
        sides = [
            min(x1 - x0, y1 - y0)
            for x0, y0, x1, y1 in (r.polygon.bounds for r in b.rooms if r.label.value == "big")
        ]
        out.append((b.metadata["shape"], max(sides), len(b.rooms)))
    return out


def test_blocks__deep_core_strips_make_fewer_and_deeper_big_rooms(monkeypatch):
    # a facade strip is about 5-7 m deep, a ring's core about twice that: rooms as deep as
    # the core are only possible where a core section is one strip
    shallow = _deepest_big_and_rooms(monkeypatch, 0.0)
    deep = _deepest_big_and_rooms(monkeypatch, 1.0)
    rings = [k for k, (shape, _, _) in enumerate(deep) if shape.startswith("ring")]
    assert len(rings) >= 4
    assert all(deep[k][2] < shallow[k][2] for k in rings)
    assert all(deep[k][1] > shallow[k][1] for k in rings)


def test_paint__blocks_drawn_for_many_areas_tile_without_overlap_or_void():
    for seed in range(300):
        rng = np.random.default_rng(seed)
        style = SCHOOL_BLOCKS if seed % 2 else OFFICE_BLOCKS
        dims = Dims(int(rng.integers(20, 35)), int(rng.integers(50, 90)), 30, 7000)
        section, length = draw_section(rng, int(rng.uniform(300, 8000) * 100), dims, style, 4, 7000)
        r = paint_block(section, length)
        shapes = [box(*x) for x in _rects(r)]
        union = unary_union(shapes + [box(*h) for h in r.holes])
        assert sum(p.area for p in shapes) == pytest.approx(unary_union(shapes).area), seed
        assert union.geom_type == "Polygon" and not union.interiors, seed


@pytest.mark.parametrize(("kind", "least"), [("office", 0.85), ("school", 0.6)])
def test_blocks__footprints_are_compact(kind, least, samples):
    # real plans' median fill: offices 0.94, schools 0.80 (interquartile range 0.70-0.93; the
    # larger schools are L, T and U shapes); the old wing layout gave 0.48 and 0.65
    fills = [building_measures(b).footprint_fill for b in samples(kind)[:40]]
    assert np.median(fills) >= least


@pytest.mark.parametrize("kind", ["office", "school"])
def test_blocks__less_than_two_fifths_of_the_floor_is_circulation(kind, samples):
    shares = [building_measures(b).circulation_share for b in samples(kind)[:40]]
    assert np.median(shares) <= 0.4


def test_blocks__the_papers_model_keeps_the_wing_layout():
    b = make_generator("office", 2000, model="paper")(np.random.default_rng(0))
    assert b.metadata["shape"] in {"bar", "L", "T", "cross", "U", "H", "E", "comb", "court", "deep", "grid"}
    assert b.metadata["params"]["model"] == "office"


def test_blocks__layout_and_model_names_are_checked():
    with pytest.raises(ConfigError, match="unknown layout 'maze'; valid: blocks, wings"):
        make_generator("office", layout="maze")
    with pytest.raises(ConfigError, match="unknown model 'tabel'"):
        make_generator("school", model="tabel")


def test_compose__an_e_stands_its_wings_evenly_on_the_main_bar():
    from realistic_indoor.generator.blocks.compose import compose

    rng = np.random.default_rng(4)
    dims = Dims(corridor=25, depth=80, shallow=35, hall_area=6000)
    regions = compose(rng, "E", 500_000, dims, SCHOOL_BLOCKS, 3, 6000.0, wings=3)
    assert regions is not None
    # the main bar's corridor plus, per wing, its connector and its own corridor
    assert len(regions.corridors) >= 1 + 2 * 3
    shape = unary_union([box(*r) for r in regions.corridors + [b.rect for b in regions.bays]])
    assert shape.geom_type == "Polygon"  # one connected footprint


def test_compose__a_ring_with_a_wing_joins_the_wing_to_the_ring_s_north_corridor():
    from realistic_indoor.generator.blocks.compose import compose

    ring_main = replace(OFFICE_BLOCKS, ring_main_p=1.0)
    dims = Dims(corridor=20, depth=60, shallow=30, hall_area=6000)
    made = 0
    for seed in range(20):
        regions = compose(np.random.default_rng(seed), "L", 250_000, dims, ring_main, 3, 6000.0)
        if regions is None:
            continue
        made += 1
        rects = _rects(regions)
        shapes = [box(*r) for r in rects]
        union = unary_union(shapes)
        assert sum(p.area for p in shapes) == pytest.approx(union.area), seed  # nothing overlaps
        assert union.geom_type == "Polygon", seed
        corridors = unary_union([box(*r) for r in regions.corridors])
        assert corridors.geom_type == "Polygon", seed  # one corridor network, ring and wing
        # a ring (two long corridors) and a wing beside it: not one convex block
        assert union.area / union.convex_hull.area < 0.95, seed
    assert made >= 10


def test_schools__without_rings_as_often_as_the_real_plans(samples):
    """The fitted share of real schools whose corridors close a loop is 0.15: most generated
    schools of the default size are bars, L, T, U or E shapes, whose corridors form a tree."""
    from realistic_indoor.building.topology import circulation_loops

    rings = np.mean([circulation_loops(b) > 0 for b in samples("school")[:100]])
    assert rings < 0.4
