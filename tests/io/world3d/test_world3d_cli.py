"""The 3D worlds on the command line: ``convert`` and ``generate -o``, with the wall options."""

from __future__ import annotations

import pytest

from realistic_indoor.cli import main
from realistic_indoor.io import save


@pytest.fixture
def plan_json(tiny_office, tmp_path):
    path = tmp_path / "tiny.json"
    save(tiny_office, path)
    return path


def _one_line_error(capsys, *words: str) -> None:
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "Traceback" not in err, err
    for word in words:
        assert word in err


def test_convert__to_a_gazebo_world_with_options(plan_json, tmp_path, capsys):
    out = tmp_path / "tiny.sdf"
    assert main(["convert", str(plan_json), "-o", str(out), "--wall-height", "3", "--closed-entrances"]) == 0
    assert f"wrote {out}" in capsys.readouterr().out
    text = out.read_text(encoding="utf-8")
    assert "<size>10.1 0.1 3</size>" in text  # the corridor's 10 m wall, 3 m high
    assert '<collision name="door_e1_collision">' in text


def test_convert__folder_to_meshes(plan_json, tmp_path, capsys):
    assert (
        main(["convert", str(plan_json.parent), "--out-dir", str(tmp_path / "out"), "--format", "glb"]) == 0
    )
    assert (tmp_path / "out" / "tiny.glb").read_bytes()[:4] == b"glTF"


def test_convert__ros_map_takes_the_wall_thickness(plan_json, tmp_path):
    assert main(["convert", str(plan_json), "-o", str(tmp_path / "m.yaml"), "--wall-thickness", "0.3"]) == 0
    thin = tmp_path / "thin.yaml"
    assert main(["convert", str(plan_json), "-o", str(thin)]) == 0
    assert tmp_path.joinpath("m.pgm").read_bytes().count(0) > tmp_path.joinpath(
        "thin.pgm"
    ).read_bytes().count(0)


@pytest.mark.parametrize(
    ("flags", "words"),
    [
        (["--wall-height", "0"], ["--wall-height must be a finite number in [0.1, 10] m, got 0.0"]),
        (["--wall-height", "-2"], ["--wall-height must be"]),
        (["--door-height", "3"], ["--door-height must be at most --wall-height"]),
        (["--wall-thickness", "0"], ["--wall-thickness must be"]),
        (["--wall-thickness", "100"], ["--wall-thickness must be a finite number in [0.01, 1] m, got 100.0"]),
    ],
)
def test_convert__bad_options_are_one_line_errors(plan_json, tmp_path, capsys, flags, words):
    out = tmp_path / "tiny.mjcf.xml"
    assert main(["convert", str(plan_json), "-o", str(out), *flags]) == 1
    _one_line_error(capsys, *words)
    assert not out.exists()


def test_convert__3d_options_on_another_format_are_refused(plan_json, tmp_path, capsys):
    assert main(["convert", str(plan_json), "-o", str(tmp_path / "x.json"), "--wall-height", "3"]) == 1
    _one_line_error(capsys, "--wall-height applies to 3D worlds", "x.json")


def test_convert__unknown_ending_lists_the_3d_ones(plan_json, tmp_path, capsys):
    assert main(["convert", str(plan_json), "-o", str(tmp_path / "x.dae")]) == 1
    _one_line_error(capsys, "x.dae", ".sdf", ".world", ".mjcf.xml", ".glb", ".obj")


def test_generate__writes_a_world_and_checks_options_first(tmp_path, capsys):
    out = tmp_path / "house.world"
    assert main(["generate", "--type", "house", "--seed", "3", "-o", str(out), "--door-height", "2"]) == 0
    assert '<sdf version="1.9">' in out.read_text(encoding="utf-8")
    capsys.readouterr()
    assert main(["generate", "--type", "house", "-o", str(tmp_path / "h.sdf"), "--wall-height", "-1"]) == 1
    _one_line_error(capsys, "--wall-height")


def test_generate__count_into_a_folder_of_models(tmp_path):
    out = tmp_path / "maps"
    args = ["generate", "--type", "random", "--count", "2", "--out-dir", str(out), "--format", "mjcf.xml"]
    assert main([*args, "--wall-height", "2"]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["random_0.mjcf.xml", "random_1.mjcf.xml"]
