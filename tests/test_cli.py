import argparse
import subprocess
import sys
from pathlib import Path

import pytest

from realistic_indoor.cli import build_parser, main
from realistic_indoor.errors import ConfigError
from realistic_indoor.io import load, save

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def _subcommands() -> list[str]:
    parser = build_parser()
    (sub,) = (a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return sorted(sub.choices)


def _one_line_error(err: str, *names: str) -> None:
    """A user error is one line on stderr, naming the file, without a traceback."""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert "Traceback" not in err
    for name in names:
        assert name in lines[0]


@pytest.fixture
def plan_json(tiny_office, tmp_path) -> Path:
    path = tmp_path / "tiny.json"
    save(tiny_office, path)
    return path


def test_cli__main_help(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    assert out.startswith("usage: realistic-indoor")
    for name in _subcommands():
        assert name in out


def test_cli__no_command_prints_help_and_exits_2(capsys):
    assert main([]) == 2
    assert "usage: realistic-indoor" in capsys.readouterr().out


def test_cli__known_subcommands_registered():
    assert {"info", "convert", "render"} <= set(_subcommands())


@pytest.mark.parametrize("command", _subcommands())
def test_cli__every_subcommand_has_help(command, capsys):
    with pytest.raises(SystemExit) as exc:
        main([command, "--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    assert out.startswith(f"usage: realistic-indoor {command}")
    assert len(out.splitlines()) > 3


def test_cli__info_summarises_the_plan(plan_json, capsys):
    assert main(["info", str(plan_json)]) == 0
    out = capsys.readouterr().out
    assert "type: office" in out
    assert "rooms: 3 (1 corridor, 2 medium)" in out
    assert "doors: 3 (1 exterior)" in out


def test_cli__convert_to_json_and_back(plan_json, tiny_office, tmp_path, capsys):
    copy, back = tmp_path / "copy.json", tmp_path / "back.json"
    assert main(["convert", str(plan_json), "-o", str(copy)]) == 0
    assert main(["convert", str(copy), "-o", str(back)]) == 0
    assert f"wrote {back}" in capsys.readouterr().out
    assert load(back) == tiny_office


def test_cli__convert_to_ros_map_writes_both_files(plan_json, tmp_path, capsys):
    assert main(["convert", str(plan_json), "-o", str(tmp_path / "map.yaml"), "--resolution", "0.1"]) == 0
    out = capsys.readouterr().out
    assert f"wrote {tmp_path / 'map.pgm'}" in out and f"wrote {tmp_path / 'map.yaml'}" in out
    assert "resolution: 0.1" in (tmp_path / "map.yaml").read_text()


def test_cli__render_png_and_svg(plan_json, tmp_path, capsys):
    png, svg = tmp_path / "plan.png", tmp_path / "plan.svg"
    assert main(["render", str(plan_json), "-o", str(png), "--dpi", "50", "--functions"]) == 0
    assert main(["render", str(plan_json), "-o", str(svg), "--title", "Ground floor"]) == 0
    assert f"wrote {png}" in capsys.readouterr().out
    assert png.read_bytes().startswith(PNG_MAGIC)
    assert "<svg" in svg.read_text(encoding="utf-8")


def test_cli__render_dpi_sets_the_picture_size(plan_json, tmp_path):
    import matplotlib.image as mpimg

    sizes = []
    for dpi in ("40", "80"):
        out = tmp_path / f"plan{dpi}.png"
        assert main(["render", str(plan_json), "-o", str(out), "--dpi", dpi]) == 0
        sizes.append(mpimg.imread(out).shape[:2])
    assert sizes[1][0] == pytest.approx(2 * sizes[0][0], abs=1)
    assert sizes[1][1] == pytest.approx(2 * sizes[0][1], abs=1)


def test_cli__render_refuses_a_non_picture_output(plan_json, tmp_path, capsys):
    assert main(["render", str(plan_json), "-o", str(tmp_path / "plan.yaml")]) == 1
    _one_line_error(capsys.readouterr().err, "plan.yaml", ".png")


@pytest.mark.parametrize("command", ["info", "convert", "render"])
def test_cli__missing_file_is_one_line_exit_1(command, tmp_path, capsys):
    missing = tmp_path / "nowhere.json"
    extra = ["-o", str(tmp_path / "out.png")] if command != "info" else []
    assert main([command, str(missing), *extra]) == 1
    _one_line_error(capsys.readouterr().err, str(missing), "no such file")


@pytest.mark.parametrize("command", ["info", "convert", "render"])
def test_cli__malformed_file_is_one_line_exit_1(command, tmp_path, capsys):
    bad = tmp_path / "broken.json"
    bad.write_text('{"schema": "realistic-indoor/building", "rooms": [', encoding="utf-8")
    extra = ["-o", str(tmp_path / "out.png")] if command != "info" else []
    assert main([command, str(bad), *extra]) == 1
    _one_line_error(capsys.readouterr().err, str(bad))
    assert not (tmp_path / "out.png").exists()


def test_cli__console_script_exit_codes(plan_json, tmp_path):
    script = Path(sys.executable).parent / "realistic-indoor"
    if not script.exists():
        pytest.skip(f"console script not installed at {script} (pip install -e .)")
    ok = subprocess.run(
        [str(script), "render", str(plan_json), "-o", str(tmp_path / "p.png"), "--dpi", "40"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert ok.returncode == 0, ok.stderr
    assert (tmp_path / "p.png").read_bytes().startswith(PNG_MAGIC)
    missing = tmp_path / "nowhere.json"
    bad = subprocess.run([str(script), "info", str(missing)], capture_output=True, text=True, timeout=120)
    assert bad.returncode == 1
    _one_line_error(bad.stderr, str(missing))
    usage = subprocess.run([str(script), "render"], capture_output=True, text=True, timeout=120)
    assert usage.returncode == 2 and "usage:" in usage.stderr


def test_cli__info_on_a_real_plan(real_plans_dir, capsys):
    assert main(["info", str(real_plans_dir / "office" / "Off-2.xml")]) == 0
    out = capsys.readouterr().out
    assert "type: office" in out and "rooms: 31 " in out


def test_cli__render_a_real_plan_with_entrances(real_plans_dir, tmp_path, capsys):
    out = tmp_path / "off2.png"
    plan = real_plans_dir / "office" / "Off-2.xml"
    assert main(["render", str(plan), "-o", str(out), "--dpi", "50", "--infer-entrances", "--functions"]) == 0
    assert out.read_bytes().startswith(PNG_MAGIC)


def test_cli__convert_a_real_plan_to_json_keeps_it(real_plans_dir, tmp_path):
    plan = real_plans_dir / "school" / "Sabadell1_updated.xml"
    assert main(["convert", str(plan), "-o", str(tmp_path / "s.json")]) == 0
    assert load(tmp_path / "s.json") == load(plan)


def test_cli__infer_entrances_needs_a_floorplan_input(plan_json, tmp_path, capsys):
    assert main(["render", str(plan_json), "-o", str(tmp_path / "p.png"), "--infer-entrances"]) == 1
    _one_line_error(capsys.readouterr().err, str(plan_json), "floor-plan XML")


def test_convert__infer_entrances_on_json_is_a_one_line_error(tmp_path, tiny_office, capsys):
    from realistic_indoor.cli import main
    from realistic_indoor.io import save

    plan = tmp_path / "plan.json"
    save(tiny_office, plan)
    assert main(["convert", str(plan), "-o", str(tmp_path / "out.json"), "--infer-entrances"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert "floor-plan XML" in err[0]


def test_run_script__user_error_is_one_line_and_exit_1(capsys):
    from realistic_indoor.cli import run_script

    def bad() -> int:
        raise ConfigError("EnvConfig.max_steps must be an integer >= 1, got 0")

    assert run_script(bad, "train_ppo.py") == 1
    assert (
        capsys.readouterr().err == "train_ppo.py: error: EnvConfig.max_steps must be an integer >= 1, got 0\n"
    )
    assert run_script(lambda: None, "x.py") == 0


def test_run_script__a_bug_is_one_line_with_exit_code_70_and_its_traceback_under_debug(capsys, monkeypatch):
    from realistic_indoor.cli import run_script

    def buggy() -> int:
        raise KeyError("internal\nsecond line")

    monkeypatch.delenv("REALISTIC_INDOOR_DEBUG", raising=False)
    assert run_script(buggy, "x.py") == 70
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("x.py: internal error: KeyError: ")
    assert "--debug" in err and "Traceback" not in err
    with pytest.raises(KeyError):
        run_script(buggy, "x.py", debug=True)
    monkeypatch.setenv("REALISTIC_INDOOR_DEBUG", "1")
    with pytest.raises(KeyError):
        run_script(buggy, "x.py")


def test_run_script__a_file_that_cannot_be_written_is_one_line_exit_1(capsys):
    import errno

    from realistic_indoor.cli import run_script

    def full() -> int:
        raise OSError(errno.ENOSPC, "No space left on device", "out/plan.json")

    assert run_script(full, "x.py") == 1
    assert capsys.readouterr().err == (
        "x.py: error: cannot use out/plan.json: No space left on device; free some space or write elsewhere\n"
    )


def test_main_debug_option_lets_a_bug_raise(monkeypatch):
    import realistic_indoor.cli.info as info

    def broken(args):
        raise ZeroDivisionError("bug")

    monkeypatch.setattr(info, "run", broken)
    monkeypatch.delenv("REALISTIC_INDOOR_DEBUG", raising=False)
    assert main(["info", "x.json"]) == 70
    with pytest.raises(ZeroDivisionError):
        main(["--debug", "info", "x.json"])


# --- convert and render over folders: bad plans are left out, named and counted ---


@pytest.fixture
def plans_with_broken(tiny_office, tmp_path) -> Path:
    """``plans/``: ``a.json``, an empty ``broken.xml`` and ``sub/b.json`` (sorted in that order)."""
    folder = tmp_path / "plans"
    save(tiny_office, folder / "a.json")
    (folder / "broken.xml").write_text("")
    save(tiny_office, folder / "sub" / "b.json")
    return folder


def test_convert__folder_to_ros_maps_skips_the_broken_plan(plans_with_broken, tmp_path, capsys):
    out = tmp_path / "maps"
    assert main(["convert", str(plans_with_broken), "--out-dir", str(out), "--format", "yaml"]) == 0
    captured = capsys.readouterr()
    assert captured.out.splitlines() == [
        f"wrote {out / 'a.pgm'}",
        f"wrote {out / 'a.yaml'}",
        f"wrote {out / 'sub' / 'b.pgm'}",
        f"wrote {out / 'sub' / 'b.yaml'}",
    ]
    assert captured.err.splitlines() == [
        f"realistic-indoor: warning: skipped {plans_with_broken / 'broken.xml'}: malformed XML at line 1, "
        "column 1: no element found",
        f"converted 2 of 3 plans into {out}; skipped 1 of 3 plans: broken.xml",
    ]


def test_convert__folder_strict_stops_at_the_broken_plan(plans_with_broken, tmp_path, capsys):
    argv = [
        "convert",
        str(plans_with_broken),
        "--out-dir",
        str(tmp_path / "o"),
        "--format",
        "json",
        "--strict",
    ]
    assert main(argv) == 1
    _one_line_error(capsys.readouterr().err, str(plans_with_broken / "broken.xml"), "malformed XML")
    assert load(tmp_path / "o" / "a.json").rooms  # written before the broken plan was reached
    assert not (tmp_path / "o" / "sub").exists()


def test_render__folder_draws_every_good_plan(plans_with_broken, tmp_path, capsys):
    out = tmp_path / "pictures"
    assert main(["render", str(plans_with_broken), "--out-dir", str(out), "--size", "2", "--dpi", "50"]) == 0
    assert (out / "a.png").read_bytes()[:8] == PNG_MAGIC
    assert (out / "sub" / "b.png").read_bytes()[:8] == PNG_MAGIC
    assert (
        capsys.readouterr().err.splitlines()[-1]
        == f"drawn 2 of 3 plans into {out}; skipped 1 of 3 plans: broken.xml"
    )


def test_convert__folder_mistakes_are_one_line(plans_with_broken, tiny_office, tmp_path, capsys):
    save(tiny_office, plans_with_broken / "a.xml")
    cases = [
        (
            ["convert", str(plans_with_broken), "-o", str(tmp_path / "x.json")],
            "is a folder; convert its plans with --out-dir",
        ),
        (
            ["render", str(plans_with_broken), "-o", str(tmp_path / "x.png")],
            "is a folder; draw its plans with --out-dir",
        ),
        (["convert", str(plans_with_broken), "--out-dir", str(tmp_path / "o")], "--out-dir needs --format"),
        (
            ["convert", str(plans_with_broken), "--out-dir", str(tmp_path / "o"), "--format", "json"],
            f"{plans_with_broken / 'a.json'} and {plans_with_broken / 'a.xml'} would both be written to",
        ),
        (
            [
                "convert",
                str(plans_with_broken / "sub"),
                "--out-dir",
                str(plans_with_broken / "sub"),
                "--format",
                "json",
            ],
            "would be written over itself",
        ),
    ]
    for argv, message in cases:
        assert main(argv) == 1, argv
        _one_line_error(capsys.readouterr().err, message)
    assert not (tmp_path / "o").exists()


def test_checkout_commit__is_the_head_of_a_git_checkout_and_none_elsewhere(tmp_path, monkeypatch):
    import shutil

    from realistic_indoor.cli import checkout_commit

    monkeypatch.setenv("GIT_CEILING_DIRECTORIES", str(tmp_path))  # a checkout around tmp_path is not searched
    monkeypatch.delenv("GIT_DIR", raising=False)
    outside = tmp_path / "plain"
    outside.mkdir()
    assert checkout_commit(outside) is None
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    repo = tmp_path / "repo"
    repo.mkdir()
    git = ["git", "-c", "user.name=t", "-c", "user.email=t@example.org"]
    subprocess.run([*git, "init", "-q"], cwd=repo, check=True)
    assert checkout_commit(repo) is None  # no commit yet
    (repo / "a.txt").write_text("a\n")
    subprocess.run([*git, "add", "a.txt"], cwd=repo, check=True)
    subprocess.run([*git, "commit", "-q", "-m", "a"], cwd=repo, check=True)
    logged = subprocess.run(
        ["git", "log", "-1", "--format=%H"], cwd=repo, capture_output=True, text=True, check=True
    ).stdout.strip()
    assert checkout_commit(repo) == logged
    assert len(logged) == 40


def test_run_folder__out_else_the_default_and_a_new_temporary_folder_for_a_small_run(tmp_path, capsys):
    from realistic_indoor.cli import run_folder

    default = tmp_path / "runs"
    assert (
        run_folder(str(tmp_path / "mine"), default, small=True, report_only=True, name="x")
        == tmp_path / "mine"
    )
    assert run_folder(None, default, small=False, report_only=True, name="x") == default
    first = run_folder(None, default, small=True, report_only=False, name="exp")
    second = run_folder(None, default, small=True, report_only=False, name="exp")
    assert first != second and first.is_dir() and second.is_dir()
    assert first.name.startswith("exp_small_") and not any(first.iterdir())
    assert f"writing to {first}" in capsys.readouterr().out
    with pytest.raises(ConfigError, match="--report-only --small needs --out"):
        run_folder(None, default, small=True, report_only=True, name="exp")


def test_script_command__quotes_what_needs_it():
    from realistic_indoor.cli import script_command

    command = script_command("experiments/x.py", ["--out", "a b", "--small"])
    assert command == ".venv/bin/python experiments/x.py --out 'a b' --small"
