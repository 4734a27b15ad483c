"""Outputs of the command line: never over an input, replaced only with --overwrite, checked first."""

import os
from pathlib import Path

import pytest

from realistic_indoor.cli import main
from realistic_indoor.generator import generate
from realistic_indoor.io import save


@pytest.fixture
def plan(tmp_path: Path) -> Path:
    path = tmp_path / "set" / "plan.json"
    save(generate("office", area_m2=400, seed=1), path)
    return path


def _refused(argv: list[str], capsys, *words: str) -> str:
    assert main(argv) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    for word in words:
        assert word in err, err
    return err


def test_convert_onto_its_own_input_is_refused(plan, tmp_path, capsys):
    before = plan.read_bytes()
    _refused(["convert", str(plan), "-o", str(plan)], capsys, "is an input")
    link = tmp_path / "link.json"
    link.symlink_to(plan)
    _refused(["convert", str(link), "-o", str(plan), "--overwrite"], capsys, "is an input")
    hard = tmp_path / "hard.json"
    os.link(plan, hard)
    _refused(["convert", str(plan), "-o", str(hard), "--overwrite"], capsys, "is an input")
    assert plan.read_bytes() == before


def test_an_existing_output_needs_overwrite(plan, tmp_path, capsys):
    out = tmp_path / "out.png"
    out.write_bytes(b"keep")
    _refused(["render", str(plan), "-o", str(out)], capsys, "exists", "--overwrite")
    assert out.read_bytes() == b"keep"
    assert main(["render", str(plan), "-o", str(out), "--overwrite"]) == 0
    assert out.read_bytes().startswith(b"\x89PNG")


def test_a_ros_map_checks_both_of_its_files(plan, tmp_path, capsys):
    (tmp_path / "map.pgm").write_bytes(b"keep")
    _refused(["convert", str(plan), "-o", str(tmp_path / "map.yaml")], capsys, "map.pgm: exists")
    assert not (tmp_path / "map.yaml").exists()


def test_validate_report_onto_a_plan_of_its_set_is_refused(plan, capsys):
    before = plan.read_bytes()
    _refused(["validate", str(plan.parent), "-o", str(plan), "--overwrite"], capsys, "is an input")
    assert plan.read_bytes() == before


def test_generate_count_does_not_replace_plans_without_overwrite(tmp_path, capsys):
    out = tmp_path / "maps"
    out.mkdir()
    (out / "office_1.json").write_text("mine", encoding="utf-8")
    argv = ["generate", "--type", "office", "--area", "300", "--count", "2", "--out-dir", str(out)]
    err = _refused(argv, capsys, "office_1.json: exists", "1 of the 2 files")
    assert "--overwrite" in err
    assert sorted(p.name for p in out.iterdir()) == ["office_1.json"]
    assert (out / "office_1.json").read_text(encoding="utf-8") == "mine"


def test_batch_render_refuses_existing_pictures_before_drawing_any(plan, tmp_path, capsys):
    save(generate("office", area_m2=300, seed=2), plan.parent / "second.json")
    out = tmp_path / "pictures"
    out.mkdir()
    (out / "second.png").write_bytes(b"keep")
    _refused(["render", str(plan.parent), "--out-dir", str(out)], capsys, "second.png: exists")
    assert sorted(p.name for p in out.iterdir()) == ["second.png"]
