"""Writes are whole or nothing; output paths are refused before any long work."""

from __future__ import annotations

import errno

import pytest

import realistic_indoor as ri
from realistic_indoor import files
from realistic_indoor.cli import main
from realistic_indoor.errors import ConfigError


@pytest.fixture(scope="module")
def building():
    return ri.generate("house", seed=3)


def _disk_full(*_args, **_kwargs):
    raise OSError(errno.ENOSPC, "No space left on device")


def test_write_text__replaces_the_file_and_leaves_no_temporary(tmp_path):
    target = tmp_path / "a.txt"
    target.write_text("old", encoding="utf-8")
    files.write_text(target, "new")
    assert target.read_text(encoding="utf-8") == "new"
    assert [p.name for p in tmp_path.iterdir()] == ["a.txt"]


def test_write_text__disk_full_keeps_the_previous_file(tmp_path, monkeypatch):
    target = tmp_path / "a.txt"
    target.write_text("previous content", encoding="utf-8")
    monkeypatch.setattr(files.os, "fsync", _disk_full)
    with pytest.raises(OSError, match="No space left"):
        files.write_text(target, "x" * 100_000)
    assert target.read_text(encoding="utf-8") == "previous content"
    assert [p.name for p in tmp_path.iterdir()] == ["a.txt"]


@pytest.mark.filterwarnings("ignore:the building does not fit")
@pytest.mark.parametrize(
    "name", ["plan.json", "plan.xml", "plan.wg.xml", "plan.yaml", "plan.png", "plan.svg"]
)
def test_save__failed_write_keeps_the_previous_file(tmp_path, monkeypatch, building, name):
    target = tmp_path / name
    ri.save(building, target)
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}

    def fail_on_commit(tmp, path):
        tmp.write_bytes(b"half a file")  # the library wrote part of it, then the disk filled up
        _disk_full()

    monkeypatch.setattr(files, "_commit", fail_on_commit)
    with pytest.raises(OSError):
        ri.save(building, target)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before


def test_save__new_file_gets_the_usual_permissions(tmp_path, building):
    import os
    import stat

    umask = os.umask(0o022)
    try:
        (path,) = ri.save(building, tmp_path / "plan.json")
    finally:
        os.umask(umask)
    assert stat.S_IMODE(path.stat().st_mode) == 0o644


def test_check_output_path__refuses_folders_suffixes_and_files_in_the_way(tmp_path):
    (tmp_path / "dir.json").mkdir()
    (tmp_path / "file").write_text("", encoding="utf-8")
    with pytest.raises(ConfigError, match="is a folder"):
        files.check_output_path(tmp_path / "dir.json", "-o")
    with pytest.raises(ConfigError, match=r"use one of \.png"):
        files.check_output_path(tmp_path / "x.bmp", "--plot", (".png", ".svg"))
    with pytest.raises(ConfigError, match="is a file, not a folder"):
        files.check_output_path(tmp_path / "file" / "x.json", "-o")
    with pytest.raises(ConfigError, match="exists"):
        files.check_output_path(tmp_path / "file", "-o", exist_ok=False)
    assert files.check_output_path(tmp_path / "new" / "deeper" / "x.json") == tmp_path / "new/deeper/x.json"


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["generate", "-o", "{tmp}/dir.json"], "is a folder"),
        (["generate", "--png", "{tmp}/x.bmp"], "unknown file type"),
        (["generate", "--count", "2", "--out-dir", "{tmp}/file"], "is a file, not a folder"),
        (["generate", "--type", "random", "--width", "0", "--height", "9"], "--width counts 3 m grid cells"),
        (["validate", "{tmp}/none", "--plot", "{tmp}/out.bmp"], "--plot"),
        (
            ["render", "{tmp}/plan.json", "-o", "{tmp}/x.png", "--size", "150", "--dpi", "2000"],
            "exceeds the limit",
        ),
        (["render", "{tmp}/plan.json", "-o", "{tmp}/x.png", "--size", "1000"], "in [0.5, 200] inches"),
        (
            ["convert", "{tmp}/plan.json", "-o", "{tmp}/x.yaml", "--resolution", "1e-5"],
            "--resolution must be a finite number in [0.01, 1] m, got 1e-05",
        ),
    ],
)
def test_cli__bad_output_is_one_line_before_any_work(tmp_path, capsys, building, argv, message):
    (tmp_path / "dir.json").mkdir()
    (tmp_path / "file").write_text("", encoding="utf-8")
    ri.save(building, tmp_path / "plan.json")
    code = main([a.format(tmp=tmp_path) for a in argv])
    err = capsys.readouterr().err
    assert code == 1
    assert message in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert not list(tmp_path.glob("x.*"))


def test_cli__bad_model_file_names_the_file_and_the_missing_field(tmp_path, capsys):
    model = tmp_path / "model.json"
    model.write_text('{"name": "mine"}', encoding="utf-8")
    assert main(["generate", "--model", str(model)]) == 1
    err = capsys.readouterr().err
    assert str(model) in err and "no field 'labels'" in err


def test_cli__random_map_says_it_is_the_random_baseline(capsys):
    assert main(["generate", "--type", "random", "--seed", "1"]) == 0
    assert "type: office (random baseline map" in capsys.readouterr().out
