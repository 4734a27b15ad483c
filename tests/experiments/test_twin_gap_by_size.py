"""scripts/twin_gap_by_size.py: the generator diagnostic runs end to end and refuses bad input."""

import pytest
from script_loader import load_script

from realistic_indoor.building import Building, Door, Room


def _load():
    return load_script("scripts/twin_gap_by_size.py")


@pytest.mark.parametrize(
    ("area", "expected"),
    [(349.0, "< 1,200 m2"), (1200.0, "1,200-3,000 m2"), (2999.9, "1,200-3,000 m2"), (7276.0, ">= 3,000 m2")],
)
def test_band_splits_at_1200_and_3000_m2(area, expected):
    assert _load().band(area) == expected


def test_a_small_school_prints_the_gap_and_room_tables(real_plans_dir, capsys):
    plans = str(real_plans_dir / "school" / "Lamuniere1_updated.xml")  # 351 m2
    assert _load().main([plans, "--type", "school", "--twins", "2", "--workers", "1", "--per-plan"]) == 0
    out = capsys.readouterr().out
    assert "wall on 1 school plans, 2 twin(s) each (seeds 1000 on)" in out
    assert "twin - real coverage AUC:" in out
    assert "< 1,200 m2" in out and "over 1 plans" in out
    assert "rooms/ha" in out and "medium" in out
    assert "per plan (by floor area): real AUC | twins' AUC (shape)" in out
    assert "Lamuniere1_updated" in out and "351 m2" in out


def test_bad_twin_count_is_one_line_and_exit_2(real_plans_dir, capsys):
    assert _load().main([str(real_plans_dir / "school"), "--twins", "0"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["error: --twins must be >= 1, not 0"]


def test_inferred_entrances_replace_the_twins_own_by_the_real_plans_rule():
    # a corridor (0-20 x 0-2) with the only exterior door at its west end, and a hall (6-16 x 2-6)
    # on the outer wall north of it: the rule puts the door in the middle of the hall's longest
    # stretch of outer wall, its north side (10 m at y = 6; its ends are 4 m), and keeps the
    # interior door
    corridor = Room.rectangle("c", "corridor", "corridor", (0.0, 0.0, 20.0, 2.0))
    hall = Room.rectangle("h", "hall", "hall", (6.0, 2.0, 16.0, 6.0))
    inner = Door("d1", "c", "h", 11.0, 2.0, 1.0, 0.0)
    own = Door("e1", "c", None, 0.0, 1.0, 1.2, 1.5707963267948966)
    building = Building("office", (corridor, hall), (inner, own), metadata={"generator": "toy"})
    out = _load().with_inferred_entrances(building)
    exterior = [d for d in out.doors if d.room_b is None]
    assert [d for d in out.doors if d.room_b is not None] == [inner]
    assert len(exterior) == 1 and exterior[0].room_a == "h"
    assert (exterior[0].x, exterior[0].y) == pytest.approx((11.0, 6.0))
    assert exterior[0].width_m == pytest.approx(1.2)
    assert out.metadata["inferred_entrances"]["rule"] == "largest hall or lobby"
    assert out.metadata["generator"] == "toy"


def test_infer_entrances_runs_end_to_end_and_says_so(real_plans_dir, capsys):
    plans = str(real_plans_dir / "school" / "Lamuniere1_updated.xml")  # 351 m2
    args = [plans, "--type", "school", "--twins", "1", "--workers", "1", "--infer-entrances"]
    assert _load().main(args) == 0
    out = capsys.readouterr().out
    assert (
        "wall on 1 school plans, 1 twin(s) each (seeds 1000 on, entrances inferred as the real plans')" in out
    )
    assert "twin - real coverage AUC:" in out
