"""The documentation runs: every code block of README.md and docs/*.md, and the docstring examples.

Each ```python block runs on its own, in a new interpreter (``sys.executable``), from a new empty
working folder: a block must hold its own imports and set-up, as a reader copying it would need.
Each ```bash / ```sh / ```console block runs its command lines one by one with ``bash`` from a
new empty working folder, the virtual environment's scripts (``realistic-indoor``) first on the
``PATH``; set-up lines (``python3 -m venv``, ``pip install``, ``source .venv/bin/activate``) are
left out. The working folder has ``../shared`` beside it, a link to the shared data beside the
project, so the documented ``../shared/data/real_floorplans/...`` paths resolve; where the shared
data is absent (a fresh clone in a temporary folder, as in CI), the blocks that name it skip and
say so.

An HTML comment on the line before a block changes how it is tested, and is visible in the
Markdown source:

- ``<!-- docs-test: skip (REASON) -->``: not run (too long for the tests: training, full
  evaluations, the experiment); pytest prints the reason.
- ``<!-- docs-test: continues (REASON) -->``: the block goes on from the code block before it
  (for example it reads the maps that block wrote): that block runs first, in the same folder
  (files are shared, Python variables are not).

A block that fails because of a bug in the package (not in the docs) can be listed in
``KNOWN_BUGS`` with the bug: it still runs, and a failure is reported as an expected failure.

Every fenced block must name its language (``text`` for diagrams), so that no command hides in
an untested block.
"""

from __future__ import annotations

import doctest
import importlib
import os
import re
import shlex
import signal
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
BIN = Path(sys.executable).parent

PYTHON = {"python", "py"}
SHELL = {"bash", "sh", "shell", "console"}
NOT_CODE = {"text", "xml", "json", "yaml", "csv", "toml", "ini", "svg", "html", "markdown", "md"}

#: Command lines that set the project up; they are not commands the docs test runs.
SETUP = re.compile(r"^(source\s+\S*activate\b|\.\s+\S*activate\b|python3? -m venv\b|\S*pip3? install\b)")
#: The marker on the line before a block: ``<!-- docs-test: skip (reason) -->``.
MARKER = re.compile(r"^<!--\s*docs-test:\s*(?P<action>[a-z]+)\s*(?:\((?P<reason>.*)\))?\s*-->$")
FENCE = re.compile(r"^(?P<indent> {0,3})(?P<fence>```+|~~~+)\s*(?P<info>[^`\s]*)")

#: Seconds one command line (or Python block) may take before the test fails.
TIMEOUT_S = 300

#: Blocks known to fail because of a bug in the package (not in the docs): (file, text in the
#: block) -> the bug. Such a block still runs; if it fails, the test is an expected failure that
#: names the bug and the error. Remove an entry once the bug is fixed.
KNOWN_BUGS: dict[tuple[str, str], str] = {}


@dataclass(frozen=True)
class Block:
    """One fenced code block of a Markdown file.

    Attributes:
        path: The Markdown file.
        line: Line number (1-based) of the opening fence.
        lang: The fence's language, lower case ("" when none is given).
        text: The block's content.
        action: ``"run"``, ``"skip"`` or ``"continues"`` (from a ``docs-test`` marker).
        reason: The marker's reason ("" without a marker).
        previous: The code block before this one in the same file (for ``continues``).
    """

    path: Path
    line: int
    lang: str
    text: str
    action: str = "run"
    reason: str = ""
    previous: Block | None = None

    @property
    def name(self) -> str:
        """A test id: file, line and language."""
        return f"{self.path.relative_to(ROOT).as_posix()}:{self.line}:{self.lang or 'none'}"

    @property
    def kind(self) -> str:
        """``"python"``, ``"shell"`` or ``"other"``."""
        if self.lang in PYTHON:
            return "python"
        if self.lang in SHELL:
            return "shell"
        return "other"


def parse_blocks(path: Path) -> list[Block]:
    """Every fenced code block of a Markdown file, with its ``docs-test`` marker.

    Args:
        path: A Markdown file.

    Returns:
        The blocks in file order; ``previous`` links each runnable block to the runnable block
        before it.

    Raises:
        ValueError: On an unclosed fence or a malformed or unknown marker.
    """
    lines = path.read_text(encoding="utf-8").splitlines()
    blocks: list[Block] = []
    previous: Block | None = None
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        fence, start = m.group("fence"), i
        end = start + 1
        while end < len(lines) and not lines[end].strip().startswith(fence):
            end += 1
        if end == len(lines):
            raise ValueError(f"{path}:{start + 1}: code block never closed")
        action, reason = "run", ""
        before = start - 1
        while before >= 0 and not lines[before].strip():
            before -= 1
        if before >= 0 and lines[before].strip().startswith("<!-- docs-test"):
            mark = MARKER.match(lines[before].strip())
            if not mark or mark.group("action") not in ("skip", "continues"):
                raise ValueError(
                    f"{path}:{before + 1}: bad marker {lines[before].strip()!r}; "
                    "write <!-- docs-test: skip (REASON) --> or <!-- docs-test: continues (REASON) -->"
                )
            action, reason = mark.group("action"), (mark.group("reason") or "").strip()
            if not reason:
                raise ValueError(f"{path}:{before + 1}: a docs-test marker needs a reason in parentheses")
        indent = len(m.group("indent"))
        body = "\n".join(
            line[indent:] if line[:indent].isspace() else line for line in lines[start + 1 : end]
        )
        block = Block(path, start + 1, m.group("info").lower(), body + "\n", action, reason, previous)
        blocks.append(block)
        if block.kind != "other":
            previous = block
        i = end + 1
    return blocks


def all_blocks() -> list[Block]:
    """The code blocks of README.md and docs/*.md."""
    return [block for path in DOCS for block in parse_blocks(path)]


BLOCKS = all_blocks()
RUNNABLE = [b for b in BLOCKS if b.kind != "other"]


def shell_commands(text: str, console: bool = False) -> list[str]:
    """The command lines of a shell block, continuation lines joined, set-up lines left out.

    Args:
        text: The block's content.
        console: A ``console`` block: only lines starting with ``$ `` are commands (the rest is
            output).

    Returns:
        One string per command, for ``bash -c``.
    """
    commands: list[str] = []
    pending = ""
    for raw in text.splitlines():
        line = raw.rstrip()
        if console and not pending:
            if not line.startswith("$ "):
                continue
            line = line[2:]
        if line.endswith("\\"):
            pending += line[:-1] + " "
            continue
        line = (pending + line).strip()
        pending = ""
        if not line or line.startswith("#"):
            continue
        # Set-up parts of a command joined with && are left out, the rest kept.
        parts = [p.strip() for p in line.split("&&")]
        kept = [p for p in parts if not SETUP.match(p)]
        if kept:
            commands.append(" && ".join(kept))
    return commands


def _environment() -> dict[str, str]:
    """The environment of the docs' commands: the venv's scripts first, headless plotting."""
    env = dict(os.environ)
    env["PATH"] = f"{BIN}{os.pathsep}{env.get('PATH', '')}"
    env["MPLBACKEND"] = "Agg"
    env["SDL_VIDEODRIVER"] = "dummy"
    env["PYTHONUNBUFFERED"] = "1"
    return env


def _tail(text: str, lines: int = 25) -> str:
    return "\n".join(text.strip().splitlines()[-lines:])


def run_block(block: Block, cwd: Path) -> None:
    """Run one block in ``cwd``; fail with the command and its output when it fails.

    Args:
        block: A Python or shell block.
        cwd: The working folder.
    """
    env = _environment()
    if block.kind == "python":
        script = cwd.parent / f"block_{block.line}.py"
        script.write_text(block.text, encoding="utf-8")
        steps = [([sys.executable, str(script)], f"the Python block at {block.name}")]
    else:
        steps = [
            (["bash", "-c", f"set -o pipefail\n{command}"], command)
            for command in shell_commands(block.text, console=block.lang == "console")
        ]
        if not steps:
            pytest.fail(f"{block.name}: no command to run in this shell block")
    for argv, what in steps:
        start = time.perf_counter()
        code, stdout, stderr = _run(argv, cwd, env)
        if code is None:
            pytest.fail(f"{what}\ntook more than {TIMEOUT_S} s (mark the block skipped with the reason)")
        if code != 0:
            pytest.fail(
                f"{what}\nfailed (exit code {code}, {time.perf_counter() - start:.1f} s) in {cwd}:\n"
                f"{_tail(stderr) or _tail(stdout)}",
                pytrace=False,
            )


def _run(argv: list[str], cwd: Path, env: dict[str, str]) -> tuple[int | None, str, str]:
    """Run a command in its own process group; on time-out kill the group (worker processes too).

    Returns:
        The exit code (None after a time-out), stdout and stderr.
    """
    proc = subprocess.Popen(
        argv,
        cwd=cwd,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    try:
        stdout, stderr = proc.communicate(timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        stdout, stderr = proc.communicate()
        return None, stdout, stderr
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    return proc.returncode, stdout, stderr


def _chain(block: Block) -> list[Block]:
    """The blocks to run for ``block``: the ones it continues, then itself."""
    chain = [block]
    while chain[0].action == "continues":
        before = chain[0].previous
        if before is None:
            raise ValueError(f"{chain[0].name}: 'continues' but no code block before it")
        if before.action == "skip":
            raise ValueError(f"{chain[0].name}: continues {before.name}, which is skipped")
        chain.insert(0, before)
    return chain


def _known_bug(block: Block) -> str | None:
    rel = block.path.relative_to(ROOT).as_posix()
    for (name, text), bug in KNOWN_BUGS.items():
        if name == rel and text in block.text:
            return bug
    return None


@pytest.mark.parametrize("block", RUNNABLE, ids=[b.name for b in RUNNABLE])
def test_block_runs(block: Block, tmp_path: Path) -> None:
    if block.action == "skip":
        pytest.skip(f"{block.name}: docs-test: skip ({block.reason})")
    chain = _chain(block)
    if any("../shared/" in b.text or "../shared\n" in b.text for b in chain) and not SHARED.is_dir():
        reason = f"{block.name} uses ../shared/ (the shared real plans), not found at {SHARED}"
        if os.environ.get("REALISTIC_INDOOR_REQUIRE_SHARED") == "1":
            pytest.fail(f"{reason}; REALISTIC_INDOOR_REQUIRE_SHARED=1 requires it", pytrace=False)
        pytest.skip(reason)
    cwd = tmp_path / "work"
    cwd.mkdir()
    if SHARED.is_dir():
        (tmp_path / "shared").symlink_to(SHARED, target_is_directory=True)
    bug = _known_bug(block)
    try:
        for b in chain:
            run_block(b, cwd)
    except pytest.fail.Exception as error:
        if bug:
            pytest.xfail(f"package bug: {bug}\n{error}")
        raise


def test_docs_have_blocks_of_both_kinds() -> None:
    """The collector finds the blocks (a broken parser would make every test above vanish)."""
    kinds = [b.kind for b in BLOCKS]
    assert kinds.count("python") >= 10
    assert kinds.count("shell") >= 8
    assert (ROOT / "README.md") in {b.path for b in RUNNABLE}


@pytest.mark.parametrize("block", BLOCKS, ids=[b.name for b in BLOCKS])
def test_block_names_its_language(block: Block) -> None:
    """An untagged block could hide commands from the test: every block says what it holds."""
    assert block.lang in PYTHON | SHELL | NOT_CODE, (
        f"{block.name}: fenced block without a known language ({block.lang!r}); "
        "use ```python, ```bash, or ```text for anything that is not run"
    )
    if block.kind == "other":
        assert block.action == "run", f"{block.name}: a docs-test marker on a block that is never run"


def test_shell_commands_parsing() -> None:
    text = (
        "source .venv/bin/activate\n"
        "python3 -m venv .venv && .venv/bin/pip install -e .\n"
        "realistic-indoor validate a b \\\n    --type office   # compare\n"
        "# a comment\n\n"
        "cd x && realistic-indoor info p.json\n"
    )
    assert shell_commands(text) == [
        "realistic-indoor validate a b      --type office   # compare",
        "cd x && realistic-indoor info p.json",
    ]
    assert shell_commands("$ realistic-indoor info p.json\nrooms: 3\n", console=True) == [
        "realistic-indoor info p.json"
    ]
    assert shlex.split(shell_commands("realistic-indoor a \\\n  b\n")[0]) == ["realistic-indoor", "a", "b"]


def test_markers_are_parsed(tmp_path: Path) -> None:
    doc = tmp_path / "doc.md"
    doc.write_text(
        "<!-- docs-test: skip (trains for 20 minutes) -->\n```bash\nrealistic-indoor train\n```\n\n"
        "```python\nx = 1\n```\n<!-- docs-test: continues (reads x) -->\n\n```python\nprint(x)\n```\n",
        encoding="utf-8",
    )
    skipped, first, second = parse_blocks(doc)
    assert (skipped.action, skipped.reason) == ("skip", "trains for 20 minutes")
    assert second.action == "continues" and second.previous == first
    doc.write_text("<!-- docs-test: skipp (typo) -->\n```bash\nls\n```\n", encoding="utf-8")
    with pytest.raises(ValueError, match="bad marker"):
        parse_blocks(doc)


def _doctest_modules() -> list[str]:
    """The package's modules whose docstrings hold examples (``>>>``)."""
    names = []
    for path in sorted((ROOT / "realistic_indoor").rglob("*.py")):
        if ">>>" in path.read_text(encoding="utf-8"):
            parts = path.relative_to(ROOT).with_suffix("").parts
            names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return names


@pytest.mark.parametrize("module", _doctest_modules())
def test_docstring_examples(module: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The examples in the package's docstrings run and print what they show."""
    monkeypatch.chdir(tmp_path)
    mod = importlib.import_module(module)
    result = doctest.testmod(mod, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE, verbose=False)
    assert result.attempted > 0, f"{module}: no docstring example found"
    assert result.failed == 0, f"{module}: {result.failed} of {result.attempted} docstring examples failed"
