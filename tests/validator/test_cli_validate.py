import json

import pytest

from realistic_indoor.cli import main
from realistic_indoor.validator import plan_sets


def test_validate__two_folders_named_with_labels(plan_folders, capsys):
    code = main(["validate", str(plan_folders / "mazes"), str(plan_folders / "tidy"), "--labels", "m,t"])
    out = capsys.readouterr().out
    assert code == 0
    assert "Realism of 2 sets of office plans against real offices (paper: office)" in out
    assert "m vs t" in out
    assert "  m: 4 plans, 32 rooms" in out


def test_validate__json_to_a_file_and_a_plot(plan_folders, tmp_path, capsys):
    report, figure = tmp_path / "out" / "r.json", tmp_path / "out" / "f.png"
    args = [
        "validate",
        str(plan_folders / "mazes"),
        "--format",
        "json",
        "-o",
        str(report),
        "--plot",
        str(figure),
    ]
    assert main([*args, "--reference", str(plan_folders / "tidy")]) == 0
    data = json.loads(report.read_text())
    assert data["reference"]["name"] == "tidy"
    assert data["reference"]["plans"] == 4
    assert figure.stat().st_size > 10_000
    assert capsys.readouterr().out == ""


def test_validate__quoted_glob_is_one_set(plan_folders, capsys):
    assert main(["validate", str(plan_folders / "*" / "*.json"), "--format", "csv", "--no-two-sample"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0] == "section,set,subject,statistic,value"


def test_validate__bad_input_is_one_line(plan_folders, tmp_path, capsys):
    (tmp_path / "empty").mkdir()
    cases = [
        (["validate", str(tmp_path / "empty")], "no readable plans"),
        (
            ["validate", str(plan_folders / "tidy"), "--type", "castle"],
            "unknown building type 'castle'; valid types: office, school, house",
        ),
        (["validate", str(tmp_path / "missing"), "--type", "castle"], "unknown building type 'castle'"),
        (
            ["validate", str(plan_folders / "tidy"), "--type", "unknown"],
            "choose one of: office, school, house",
        ),
        (
            ["validate", str(plan_folders / "tidy"), "--labels", "a,b"],
            "--labels names 2 sets but 1 were given",
        ),
        (["validate", str(tmp_path / "missing")], "no such file or folder"),
        (["validate", str(plan_folders / "tidy"), "--reference", "mall"], "nor a paper table (paper, office"),
    ]
    for argv, message in cases:
        assert main(argv) == 1
        err = capsys.readouterr().err
        assert len(err.strip().splitlines()) == 1, err
        assert message in err


def test_validate__paper_table_by_name(plan_folders, capsys):
    assert main(["validate", str(plan_folders / "mazes"), "--reference", "robocup_2013_final_map"]) == 0
    assert "against the 2013 competition map" in capsys.readouterr().out


def test_validate__same_input_gives_the_same_bytes(plan_folders, capsys):
    argv = [
        "validate",
        str(plan_folders / "mazes"),
        str(plan_folders / "tidy"),
        "--format",
        "json",
        "--seed",
        "4",
    ]
    outputs = []
    for _ in range(2):
        assert main(argv) == 0
        outputs.append(capsys.readouterr().out)
    assert outputs[0] == outputs[1]


@pytest.fixture
def mazes_with_bad_plans(plan_folders):
    """``mazes/``: 4 good plans, an empty ``broken.xml`` and a plan without doors ``doorless.json``."""
    from realistic_indoor.building import Building, Room
    from realistic_indoor.io import save

    folder = plan_folders / "mazes"
    (folder / "broken.xml").write_text("")
    room = Room.rectangle("a", "medium", "office", (0, 0, 4, 4))
    save(Building("office", (room,), ()), folder / "doorless.json")
    return folder


def test_validate__bad_plans_are_left_out_named_counted_and_reported(mazes_with_bad_plans, capsys):
    folder = mazes_with_bad_plans
    argv = ["validate", str(folder), "--no-two-sample", "--format", "json"]
    assert main(argv) == 0
    captured = capsys.readouterr()
    err = captured.err.splitlines()
    assert (
        f"realistic-indoor: warning: skipped {folder / 'broken.xml'}: malformed XML at line 1, column 1: "
        "no element found" in err
    )
    assert any(
        line.startswith(
            f"realistic-indoor: warning: skipped {folder / 'doorless.json'}: the plan has no doors"
        )
        for line in err
    )
    # 6 plan files: 4 measured, the empty XML and the doorless plan left out
    assert (
        err[-1]
        == "skipped 2 of 6 plans: broken.xml, doorless.json (listed in the report under 'Plans left out' or 'Notes')"
    )
    (report,) = json.loads(captured.out)["sets"]
    assert report["plans"] == 4
    assert [(s["source"], s["reason"][:20]) for s in report["skipped"]] == [
        (str(folder / "broken.xml"), "malformed XML at lin"),
        (str(folder / "doorless.json"), "the plan has no door"),
    ]


def test_validate__markdown_report_lists_the_plans_left_out(mazes_with_bad_plans, capsys):
    assert main(["validate", str(mazes_with_bad_plans), "--no-two-sample", "--format", "markdown"]) == 0
    out = capsys.readouterr().out
    assert "- mazes: 4 plans, 32 rooms; 2 plans left out" in out
    assert f"### Plans left out\n\n- mazes: {mazes_with_bad_plans / 'broken.xml'}: malformed XML" in out


def test_validate__strict_stops_at_the_first_bad_plan(mazes_with_bad_plans, capsys):
    assert main(["validate", str(mazes_with_bad_plans), "--strict"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(
        f"realistic-indoor validate: error: {mazes_with_bad_plans / 'broken.xml'}: malformed XML"
    )
    (mazes_with_bad_plans / "broken.xml").unlink()
    assert main(["validate", str(mazes_with_bad_plans), "--strict"]) == 1
    assert "doorless.json: the plan has no doors" in capsys.readouterr().err


def test_validate__skip_bad_is_still_accepted_and_excludes_strict(mazes_with_bad_plans, capsys):
    assert main(["validate", str(mazes_with_bad_plans), "--skip-bad", "--no-two-sample"]) == 0
    assert "2 plans left out" in capsys.readouterr().out
    with pytest.raises(SystemExit) as e:
        main(["validate", str(mazes_with_bad_plans), "--skip-bad", "--strict"])
    assert e.value.code == 2
    assert "not allowed with argument" in capsys.readouterr().err


def test_validate__reference_folder_with_a_bad_plan(plan_folders, capsys):
    (plan_folders / "tidy" / "broken.json").write_text("{")
    argv = [
        "validate",
        str(plan_folders / "mazes"),
        "--reference",
        str(plan_folders / "tidy"),
        "--no-two-sample",
    ]
    assert main(argv) == 0
    captured = capsys.readouterr()
    assert f"reference tidy: left out {plan_folders / 'tidy' / 'broken.json'}: " in captured.out
    assert captured.err.splitlines()[-1].startswith("skipped 1 of 9 plans: broken.json")


def test_validate__progress_on_a_terminal_and_none_with_quiet(plan_folders, monkeypatch, capsys):
    monkeypatch.setattr(plan_sets, "show_progress", lambda quiet=False: not quiet)
    argv = ["validate", str(plan_folders / "mazes"), str(plan_folders / "tidy")]
    assert main(argv) == 0
    err = capsys.readouterr().err
    for stage in (
        "reading mazes",
        "reading tidy",
        "measuring mazes",
        "measuring tidy",
        "two-sample test mazes vs tidy",
    ):
        assert stage in err
    assert main([*argv, "--quiet"]) == 0
    assert capsys.readouterr().err == ""


def test_validate__a_reference_folder_is_named_by_its_path_not_only_its_type(plan_folders, capsys):
    import shutil

    shutil.copytree(plan_folders / "mazes", plan_folders / "generated" / "office")
    shutil.copytree(plan_folders / "tidy", plan_folders / "real" / "office")
    argv = [str(plan_folders / "generated" / "office"), "--reference", str(plan_folders / "real" / "office")]
    assert main(["validate", *argv, "--no-two-sample"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0].startswith("Realism of 1 set of office plans against real/office")
    header = next(line for line in out.splitlines() if line.startswith("label "))
    assert header.split()[-2:] == ["office", "real/office"]
    # where the folder's last two parts name a set as well, "reference" is put before them
    sets = [str(plan_folders / "generated" / "office"), str(plan_folders / "real" / "office")]
    both = [*sets, "--labels", "office,real/office", "--reference", str(plan_folders / "real" / "office")]
    assert main(["validate", *both, "--no-two-sample"]) == 0
    assert "against reference real/office" in capsys.readouterr().out
