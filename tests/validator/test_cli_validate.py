import json

from realistic_indoor.cli import main


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
        (["validate", str(plan_folders / "tidy"), "--type", "castle"], "unknown building type 'castle'"),
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
