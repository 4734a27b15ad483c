"""The command line prints warnings as one line each and counts repairs beyond the first plan's."""

from __future__ import annotations

import warnings

from realistic_indoor.cli import run_script
from realistic_indoor.io.floorplan.repairs import PlanRepairWarning


def _repairs() -> int:
    for plan, count in (("a.xml", 2), ("b.xml", 3), ("c.xml", 1)):
        for i in range(count):
            warnings.warn(f'{plan}: space id="{i}": cut the overlap', PlanRepairWarning, stacklevel=1)
    warnings.warn("something else", UserWarning, stacklevel=1)
    return 0


def test_run_script__shows_the_first_plans_repairs_and_counts_the_rest(capsys):
    with warnings.catch_warnings():
        warnings.simplefilter("always")
        assert run_script(_repairs, "test") == 0
    lines = capsys.readouterr().err.splitlines()
    assert lines[:2] == [
        'realistic-indoor: warning: a.xml: space id="0": cut the overlap',
        'realistic-indoor: warning: a.xml: space id="1": cut the overlap',
    ]
    assert lines[2] == "realistic-indoor: warning: something else"
    assert lines[3].startswith("realistic-indoor: warning: 4 repairs in 2 more plans not shown")
    assert len(lines) == 4
