"""scripts/twin_gap_by_size.py: the generator diagnostic runs end to end and refuses bad input."""

import pytest
from script_loader import load_script


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
