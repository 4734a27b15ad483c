"""experiments/realism_pictures.py: which plans it picks, one scale per pair, the same bytes each run."""

import math

import pytest
from script_loader import load_script


def _load():
    load_script("experiments/layout_realism.py")  # the script imports it as a sibling module
    return load_script("experiments/realism_pictures.py")


def _office(width_m):
    """An office ``width_m`` long and 6 m deep: a corridor along it and two offices off it."""
    from realistic_indoor.building import Building, Door, Room

    half = width_m / 2
    rooms = (
        Room.rectangle("c", "corridor", "corridor", (0, 0, width_m, 2)),
        Room.rectangle("a", "medium", "office", (0, 2, half, 6)),
        Room.rectangle("b", "medium", "office", (half, 2, width_m, 6)),
    )
    doors = (
        Door("d1", "a", "c", half / 2, 2.0, 0.9, 0.0),
        Door("d2", "b", "c", 1.5 * half, 2.0, 0.9, 0.0),
        Door("e1", "c", None, 0.0, 1.0, 1.2, math.pi / 2),
    )
    return Building("office", rooms, doors, {"generator": "hand-made", "seed": 3})


def test_pick_by_area__the_middle_plan_of_each_equal_group():
    areas = [float(a) for a in range(100, 1600, 100)]  # 15 plans, already in order
    assert _load().pick_by_area(areas, 4) == [1, 5, 9, 13]


def test_pick_by_area__sorts_by_area_and_never_takes_the_extremes():
    areas = [9261.0, 300.0, 1200.0, 800.0, 2500.0, 500.0]
    picked = _load().pick_by_area(areas, 2)
    assert picked == [5, 4]  # 500 and 2,500 m2: ranks 1 and 4 (from 0) of 6
    assert 0 not in picked and 1 not in picked


def test_pick_by_area__all_plans_when_there_are_few_and_refuses_zero():
    module = _load()
    assert module.pick_by_area([30.0, 10.0, 20.0], 4) == [1, 2, 0]
    with pytest.raises(ValueError, match="count must be >= 1"):
        module.pick_by_area([1.0], 0)


def test_pairs_figure__real_and_twin_share_one_scale():
    from realistic_indoor.io.render.draw import plan_limits

    module = _load()
    real, twin = _office(10.0), _office(30.0)
    fig = module.pairs_figure([module.Pair("small", real, twin)], "test", dpi=100.0)
    fig.canvas.draw()
    per_metre = []
    for ax, building in zip(fig.axes, (real, twin), strict=True):
        x0, _y0, x1, _y1 = plan_limits(building)
        per_metre.append(ax.get_window_extent().width / (x1 - x0))
    assert per_metre[0] == pytest.approx(per_metre[1], rel=1e-6)


def test_write_png__same_pairs_same_bytes(tmp_path):
    module = _load()
    pairs = [module.Pair("a", _office(10.0), _office(12.0)), module.Pair("b", _office(20.0), _office(18.0))]
    for name in ("one.png", "two.png"):
        module.write_png(module.pairs_figure(pairs, "test", dpi=60.0), tmp_path / name)
    assert (tmp_path / "one.png").read_bytes() == (tmp_path / "two.png").read_bytes()


def test_main__draws_the_chosen_offices_beside_their_twins(real_plans_dir, tmp_path, capsys):
    out = tmp_path / "pictures"
    assert (
        _load().main(["--types", "office", "--count", "2", "--plans", str(real_plans_dir), "--out", str(out)])
        == 0
    )
    assert (out / "office_pairs.png").stat().st_size > 10_000
    assert capsys.readouterr().out.startswith("office: ")
