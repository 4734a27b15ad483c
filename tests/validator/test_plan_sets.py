import sys
from pathlib import Path

import pytest

from realistic_indoor.building import Building, Room
from realistic_indoor.errors import ConfigError, PlanFormatError
from realistic_indoor.validator.plan_sets import (
    PlanBatch,
    PlanSet,
    SkippedPlan,
    SkippedPlanWarning,
    load_plan_set,
    plan_files,
    plan_problem,
    show_progress,
    skipped_summary,
)


def test_plan_files__folder_keeps_readable_plans_only(plan_folders):
    files = plan_files(plan_folders / "mazes")
    assert [f.name for f in files] == [f"mazes_{i}.json" for i in range(4)]


def test_plan_files__glob_pattern_and_single_file(plan_folders):
    assert len(plan_files(str(plan_folders / "*" / "*_1.json"))) == 2
    one = plan_folders / "tidy" / "tidy_0.json"
    assert plan_files(one) == [one]


def test_plan_files__missing_path_is_a_clear_error(tmp_path):
    with pytest.raises(ConfigError, match="no such file or folder"):
        plan_files(tmp_path / "nope")


def test_load_plan_set__named_after_the_folder_with_sources(plan_folders):
    s = load_plan_set(plan_folders / "tidy")
    assert s.name == "tidy"
    assert len(s) == 4
    assert s.sources[0].endswith("tidy_0.json")
    assert load_plan_set([plan_folders / "tidy", plan_folders / "mazes"], "both").name == "both"


def test_load_plan_set__empty_folder_says_so(tmp_path):
    (tmp_path / "empty").mkdir()
    with pytest.raises(ConfigError, match="set 'empty': no readable plans"):
        load_plan_set(tmp_path / "empty")


@pytest.fixture
def folder_with_broken(tmp_path, tiny_office):
    """``plans/``: two good JSON plans and an empty ``broken.xml`` between them (sorted order)."""
    from realistic_indoor.io import save

    folder = tmp_path / "plans"
    save(tiny_office, folder / "a.json")
    save(tiny_office, folder / "c.json")
    (folder / "broken.xml").write_text("")
    return folder


def test_load_plan_set__unreadable_plan_is_left_out_with_a_warning(folder_with_broken):
    broken = folder_with_broken / "broken.xml"
    with pytest.warns(SkippedPlanWarning) as caught:
        s = load_plan_set(folder_with_broken)
    reason = "malformed XML at line 1, column 1: no element found"
    assert [str(w.message) for w in caught] == [f"skipped {broken}: {reason}"]
    assert [Path(src).name for src in s.sources] == ["a.json", "c.json"]
    assert s.skipped == (SkippedPlan(str(broken), reason),)


def test_load_plan_set__strict_stops_at_the_first_unreadable_plan(folder_with_broken):
    with pytest.raises(PlanFormatError, match=r"broken\.xml: malformed XML"):
        load_plan_set(folder_with_broken, strict=True)


def test_load_plan_set__no_plan_readable_is_an_error(tmp_path):
    (tmp_path / "bad.json").write_text("{not json")
    with (
        pytest.warns(SkippedPlanWarning, match=r"bad\.json"),
        pytest.raises(ConfigError, match=r"none of its 1 plans can be read, e\.g\. .*bad\.json: "),
    ):
        load_plan_set(tmp_path)


def test_plan_batch__counts_what_it_skipped(folder_with_broken):
    batch = PlanBatch(plan_files(folder_with_broken))
    with pytest.warns(SkippedPlanWarning):
        names = [path.name for path, _b in batch]
    assert names == ["a.json", "c.json"]
    assert batch.summary() == "skipped 1 of 3 plans: broken.xml"
    assert PlanBatch([folder_with_broken / "a.json"]).summary() is None
    assert skipped_summary([SkippedPlan("x/y.json", "?")], 1) == "skipped 1 of 1 plan: y.json"


def test_show_progress__only_on_a_terminal_and_not_quiet(monkeypatch):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    assert show_progress() is True
    assert show_progress(quiet=True) is False
    monkeypatch.setattr(sys.stderr, "isatty", lambda: False)
    assert show_progress() is False


def test_plan_set_of__sources_from_metadata(maze_office, tiny_office):
    s = PlanSet.of("x", [maze_office, tiny_office, Building("office", ())])
    assert s.sources == ("maze_office", "hand-made", "x[2]")


def test_plan_problem__no_rooms_or_no_doors(maze_office):
    assert plan_problem(maze_office) is None
    assert "no rooms" in plan_problem(Building("office", ()))
    doorless = Building("office", (Room.rectangle("a", "medium", "office", (0, 0, 4, 4)),))
    assert "no doors" in plan_problem(doorless)
