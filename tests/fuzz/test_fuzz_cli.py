"""Property-based fuzzing of the command line: malformed arguments never crash it or touch inputs.

Arguments are drawn from each verb's options with hostile values (negative, zero, NaN, infinite,
huge, empty, text for numbers, paths that are folders, inputs or missing). The contract: exit code
0, 1 or 2 (never 70, an internal error), a refusal is one ``error:`` line (argparse's usage line
and warnings may come before it), and no file outside the output folder changes.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import shutil
from pathlib import Path

import pytest
from fuzz_settings import fuzz
from hypothesis import given
from hypothesis import strategies as st

from realistic_indoor.cli import main

CORPUS = Path(__file__).resolve().parents[1] / "data" / "hostile"
FUZZ = fuzz(400)

NUMBERS = st.sampled_from(
    ["-1", "0", "nan", "inf", "-inf", "1e308", "abc", "", "1e-300", "3.5", "99999999999"]
)
PLANS = st.sampled_from(["@house.json", "@house.xml", "@small.wg.xml", "@missing.json", "@", "@empty.json"])
NEW_OUTPUTS = ["out/x.png", "out/x.json", "out/x.yaml", "out", "out/x.txt", ""]
OUTPUTS = st.sampled_from([*NEW_OUTPUTS, "@house.json"])  # for verbs that read house.json
GENERATED = st.sampled_from(NEW_OUTPUTS)  # generate reads no plan: any existing file may be replaced

VERB_OPTIONS: dict[str, dict[str, st.SearchStrategy[str]]] = {
    "info": {},
    "render": {"--dpi": NUMBERS, "--size": NUMBERS, "-o": OUTPUTS},
    "convert": {
        "--resolution": NUMBERS,
        "--wall-height": NUMBERS,
        "--wall-thickness": NUMBERS,
        "-o": OUTPUTS,
    },
    "validate": {
        "--worst": NUMBERS,
        "--seed": NUMBERS,
        "-o": OUTPUTS,
        "--type": st.sampled_from(["office", "x", ""]),
    },
    "generate": {
        "--area": NUMBERS,
        "--seed": NUMBERS,
        "--count": st.sampled_from(["-1", "0", "x", ""]),
        "--type": st.sampled_from(["office", "house", "random", "castle"]),
        "-o": GENERATED,
        "--width": NUMBERS,
        "--height": NUMBERS,
    },
}


def _hashes(folder: Path) -> dict[str, str]:
    return {
        str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest()
        for p in sorted(folder.rglob("*"))
        if p.is_file() and "out" not in p.relative_to(folder).parts
    }


@st.composite
def command_lines(draw: st.DrawFn) -> list[str]:
    verb = draw(st.sampled_from(sorted(VERB_OPTIONS)))
    argv = [verb]
    if verb != "generate":
        argv.append(draw(PLANS))
    elif draw(st.booleans()):
        argv += ["--area", "120", "--type", "house"]  # a fast valid building, so outputs get written
    options = VERB_OPTIONS[verb]
    for option in (
        draw(st.lists(st.sampled_from(sorted(options)), unique=True, max_size=3)) if options else []
    ):
        argv += [option, draw(options[option])]
    if verb in ("render", "convert") and "-o" not in argv:
        argv += ["-o", "out/x.png" if verb == "render" else "out/x.json"]
    if draw(st.booleans()):
        argv.append("--overwrite" if verb != "info" else "--strict")
    return argv


@pytest.fixture(scope="module")
def workspace(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("cli_fuzz")
    for name in ("house.json", "house.xml", "small.wg.xml", "empty.json"):
        shutil.copy(CORPUS / name, folder / name)
    return folder


@FUZZ
@given(argv=command_lines())
def test_malformed_command_lines_are_refused_in_one_line_and_touch_no_input(workspace, argv):
    argv = [a.replace("@", f"{workspace}/") if a.startswith("@") else a for a in argv]
    argv = [str(workspace / a) if a.startswith("out") else a for a in argv]
    before = _hashes(workspace)
    err, out = io.StringIO(), io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
        try:
            code = main(argv)
        except SystemExit as e:  # argparse's usage errors
            code = e.code
    lines = [line for line in err.getvalue().splitlines() if line.strip()]
    assert code in (0, 1, 2), (argv, err.getvalue())
    if code != 0:
        errors = [line for line in lines if "error:" in line]
        others = [line for line in lines if "error:" not in line and "warning:" not in line]
        assert len(errors) == 1, (argv, lines)
        assert all(line.startswith("usage:") or line.startswith(" ") for line in others), (argv, lines)
    assert "Traceback" not in err.getvalue()
    assert _hashes(workspace) == before, argv
    shutil.rmtree(workspace / "out", ignore_errors=True)
