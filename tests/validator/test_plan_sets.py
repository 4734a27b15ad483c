import pytest

from realistic_indoor.building import Building, Room
from realistic_indoor.errors import ConfigError, PlanFormatError
from realistic_indoor.validator.plan_sets import PlanSet, load_plan_set, plan_files, plan_problem


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


def test_load_plan_set__unreadable_plan_names_the_file(tmp_path):
    (tmp_path / "bad.json").write_text("{not json")
    with pytest.raises(PlanFormatError, match=r"bad\.json"):
        load_plan_set(tmp_path)


def test_plan_set_of__sources_from_metadata(maze_office, tiny_office):
    s = PlanSet.of("x", [maze_office, tiny_office, Building("office", ())])
    assert s.sources == ("maze_office", "hand-made", "x[2]")


def test_plan_problem__no_rooms_or_no_doors(maze_office):
    assert plan_problem(maze_office) is None
    assert "no rooms" in plan_problem(Building("office", ()))
    doorless = Building("office", (Room.rectangle("a", "medium", "office", (0, 0, 4, 4)),))
    assert "no doors" in plan_problem(doorless)
