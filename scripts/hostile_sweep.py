"""Feed every command and the Python API hostile input, and report how each case was handled (issue 35).

Each case runs in a folder of its own under a fresh temporary folder: the corpus of
``tests/data/hostile/`` and a few real plans are copied there first, so nothing of the
repository or of the shared data is ever touched. A case declares what it expects:

- ``refuse``: a user error: exit 1 or 2 and one line on stderr (``realistic-indoor: warning:``
  lines are allowed around it; an argparse usage error may print its usage lines first);
- ``repair``: exit 0 with a ``warning:`` line;
- ``handled``: either of those: the input may be refused or repaired, never accepted silently;
- ``accept``: exit 0;
- ``any``: any clean outcome (only crashes, destroyed files and leftovers count).

Whatever it expects, no case may print a traceback, end in an internal error (exit 70), change
or remove a file that existed before it (except the outputs it declares), or leave a new file or
folder behind when it is refused. Each result is classified ``ok`` or by its problems:
``traceback``, ``internal_error``, ``timeout``, ``destroyed``, ``leftover``, ``silent_accept``
(exit 0 where a refusal or a repair was expected), ``unwarned`` (a repair without a warning),
``wrong_exit`` and ``multi_line``.

Command cases run in this process through ``realistic_indoor.cli.main`` (an exception escaping
it counts as a traceback); a few run as ``python -m realistic_indoor.cli`` to check the real exit
codes, and those that may allocate gigabytes run in a child process with a memory limit. API
cases count a :class:`~realistic_indoor.errors.RealisticIndoorError` or a ``gymnasium.error.Error``
as a refusal and any other exception as a crash.

Usage::

    .venv/bin/python scripts/hostile_sweep.py [--only SUBSTRING] [--json PATH] [--keep]
    .venv/bin/python scripts/hostile_sweep.py --write-corpus   # rebuild tests/data/hostile/

Exits 0 only when every case is ok.
"""

from __future__ import annotations

import argparse
import contextlib
import dataclasses
import fnmatch
import functools
import hashlib
import importlib
import io
import json
import math
import os
import re
import resource
import shlex
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import time
import traceback
import warnings
import zipfile
from collections import Counter
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parent.parent
CORPUS = REPO / "tests" / "data" / "hostile"
REAL_PLANS = REPO.parent / "shared" / "data" / "real_floorplans"  # ../shared beside the checkout
REAL_PICKS = ("office/Milano-1.xml", "school")  # one office plan and the smallest school plan
TRACEBACK = "Traceback (most recent call last)"
WARNING_PREFIX = "realistic-indoor: warning:"
EXPECTATIONS = ("refuse", "repair", "handled", "accept", "any")
PROBLEMS = (
    "traceback",
    "internal_error",
    "timeout",
    "destroyed",
    "leftover",
    "silent_accept",
    "unwarned",
    "wrong_exit",
    "multi_line",
)
IS_ROOT = hasattr(os, "geteuid") and os.geteuid() == 0
READ_ONLY_EXPECT = "any" if IS_ROOT else "refuse"
"""Root writes into read-only folders, so there a read-only output folder proves nothing."""
INPROCESS_TIMEOUT_S = 90.0
CHILD_TIMEOUT_S = 120.0
CHILD_MEMORY_GB = 3.0
HASH_LIMIT = 64 << 20
"""Files larger than this (only the sweep's own sparse files) are compared by size and time stamps."""


# -- the data model ---------------------------------------------------------------------------------


@dataclass(frozen=True)
class Ctx:
    """Where a case runs.

    Attributes:
        inputs: The shared folder of input files (the corpus, real plans, derived sets).
        work: The case's own folder, the working directory while it runs.
    """

    inputs: Path
    work: Path


Setup = Callable[[Ctx], None]
ApiCall = Callable[[Ctx], object]


@dataclass(frozen=True)
class Case:
    """One hostile case.

    Attributes:
        name: Unique name, ``category/what/how``.
        category: The verb (``info``, ..., ``train``) or ``api``.
        expect: One of :data:`EXPECTATIONS`.
        argv: Command-line arguments (without the program name); ``@/`` stands for the inputs
            folder. Empty for API cases.
        call: The API call, for API cases.
        setup: Steps preparing the case folder before it runs.
        outputs: Glob patterns, relative to the case folder, of the files the case may create or
            change; every other file present before it must survive unchanged.
        run_in: ``process`` (this process), ``cli`` (``python -m realistic_indoor.cli``) or
            ``child`` (this script in a child process with a memory limit).
        timeout_s: Seconds before the case counts as hung.
    """

    name: str
    category: str
    expect: str
    argv: tuple[str, ...] = ()
    call: ApiCall | None = None
    setup: tuple[Setup, ...] = ()
    outputs: tuple[str, ...] = ()
    run_in: str = "process"
    timeout_s: float = INPROCESS_TIMEOUT_S


@dataclass
class Outcome:
    """What happened when a case ran.

    Attributes:
        exit_code: The exit code (an API call: 0 if it returned, 1 if it raised a user error);
            ``None`` when it crashed or hung.
        stdout: What it printed.
        stderr: Its error output (an API call: the user error's message).
        error: The traceback of an exception that escaped, or a child's death.
        warned: Whether it printed (or raised, for the API) a warning.
        timed_out: Whether it ran past its time.
        changed: Files that existed before and were changed or removed.
        created: Paths that did not exist before.
        seconds: Wall time.
    """

    exit_code: int | None = None
    stdout: str = ""
    stderr: str = ""
    error: str = ""
    warned: bool = False
    timed_out: bool = False
    changed: list[str] = field(default_factory=list)
    created: list[str] = field(default_factory=list)
    seconds: float = 0.0


class CaseTimeout(BaseException):
    """Raised by the alarm in a case that runs past its time."""


# -- classification ---------------------------------------------------------------------------------


def one_line_error(stderr: str, exit_code: int | None) -> bool:
    """Whether a refusal's error output is one line (warnings aside; usage lines allowed with exit 2)."""
    lines = [line for line in stderr.splitlines() if line.strip()]
    others = [line for line in lines if not line.startswith(WARNING_PREFIX)]
    if not others:
        return False
    if exit_code == 2 and len(others) > 1:
        usage = others[:-1]
        return usage[0].startswith("usage:") and all(line.startswith(" ") for line in usage[1:])
    return len(others) == 1


def is_temporary(path: str) -> bool:
    """Whether ``path`` looks like a temporary file of an atomic write (``.NAME.xxxx.tmp.EXT``)."""
    name = Path(path).name
    return name.startswith(".") and ".tmp" in name


def classify(expect: str, out: Outcome) -> list[str]:
    """The problems of an outcome, in :data:`PROBLEMS` order; empty when the case is ok.

    Args:
        expect: The case's expectation, one of :data:`EXPECTATIONS`.
        out: What happened.
    """
    problems: set[str] = set()
    text = "\n".join((out.stdout, out.stderr, out.error))
    if out.timed_out:
        problems.add("timeout")
    elif out.exit_code is None or TRACEBACK in text:
        problems.add("traceback")
    elif out.exit_code == 70 or "internal error" in out.stderr.lower():
        problems.add("internal_error")
    else:
        problems.update(_exit_problems(expect, out))
    if out.changed:
        problems.add("destroyed")
    if (out.created and out.exit_code != 0) or any(is_temporary(p) for p in out.created):
        problems.add("leftover")
    return [p for p in PROBLEMS if p in problems]


def _exit_problems(expect: str, out: Outcome) -> set[str]:
    """The problems of a clean exit against the expectation."""
    if out.exit_code == 0:
        if expect in ("refuse", "handled") and not (expect == "handled" and out.warned):
            return {"silent_accept"}
        if expect == "repair" and not out.warned:
            return {"unwarned"}
        return set()
    if out.exit_code not in (1, 2):
        return {"wrong_exit"}
    problems = set() if expect in ("refuse", "handled", "any") else {"wrong_exit"}
    if not one_line_error(out.stderr, out.exit_code):
        problems.add("multi_line")
    return problems


def summary_line(results: list[dict[str, Any]]) -> str:
    """``N cases: X ok, T tracebacks/internal errors, D destroyed files, ...``."""
    counts = Counter(p for r in results for p in r["problems"])
    ok = sum(1 for r in results if not r["problems"])
    crashes = sum(1 for r in results if {"traceback", "internal_error"} & set(r["problems"]))
    return (
        f"{len(results)} cases: {ok} ok, {crashes} tracebacks/internal errors, "
        f"{counts['destroyed']} destroyed files, {counts['silent_accept']} silent acceptances, "
        f"{counts['leftover']} leftovers, {counts['wrong_exit']} wrong exits, "
        f"{counts['multi_line']} multi-line errors, {counts['unwarned']} unwarned repairs, "
        f"{counts['timeout']} timeouts"
    )


# -- watching the files ------------------------------------------------------------------------------


def _fingerprint(path: Path) -> str:
    """Type, permissions and contents of ``path`` (a link's target, never followed; a FIFO unread).

    A file over :data:`HASH_LIMIT` is described by its size, time stamp and inode instead of its contents.
    """
    st = path.lstat()
    if stat.S_ISLNK(st.st_mode):
        return f"link:{os.readlink(path)}"
    if stat.S_ISDIR(st.st_mode):
        return "dir"
    if not stat.S_ISREG(st.st_mode):
        return f"special:{stat.S_IFMT(st.st_mode)}"
    if st.st_size > HASH_LIMIT:
        return f"big:{stat.S_IMODE(st.st_mode):o}:{st.st_size}:{st.st_mtime_ns}:{st.st_ino}"
    digest = hashlib.blake2b(digest_size=16)
    try:
        with path.open("rb") as f:
            for block in iter(functools.partial(f.read, 1 << 20), b""):
                digest.update(block)
    except OSError as e:
        return f"unreadable:{e.errno}"
    return f"file:{stat.S_IMODE(st.st_mode):o}:{digest.hexdigest()}"


def snapshot(folders: Iterable[Path]) -> dict[str, str]:
    """Every path under ``folders`` (not following links) with its fingerprint."""
    entries: dict[str, str] = {}
    for top in folders:
        for dirpath, dirnames, filenames in os.walk(top):
            for name in (*dirnames, *filenames):
                path = Path(dirpath) / name
                with contextlib.suppress(FileNotFoundError):
                    entries[str(path)] = _fingerprint(path)
    return entries


def compare(before: dict[str, str], after: dict[str, str], work: Path, outputs: Iterable[str]):
    """The paths changed or removed (outside ``outputs``) and the paths created.

    Returns:
        ``(changed, created)``, each a sorted list of paths.
    """
    patterns = [str(work / p) for p in outputs]

    def declared(path: str) -> bool:
        return any(fnmatch.fnmatch(path, p) or path.startswith(p.rstrip("*") + "/") for p in patterns)

    changed = sorted(p for p, fp in before.items() if after.get(p) != fp and not declared(p))
    created = sorted(p for p in after if p not in before)
    return changed, created


# -- running a case ----------------------------------------------------------------------------------


@contextlib.contextmanager
def _alarm(seconds: float) -> Iterator[None]:
    """Raise :class:`CaseTimeout` in this thread after ``seconds``."""

    def ring(signum, frame):
        raise CaseTimeout

    previous = signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


@contextlib.contextmanager
def _inside(folder: Path) -> Iterator[None]:
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        yield
    finally:
        os.chdir(cwd)


def expand(argv: Iterable[str], ctx: Ctx) -> list[str]:
    """``argv`` with ``@/`` replaced by the inputs folder."""
    return [a.replace("@/", f"{ctx.inputs}/") for a in argv]


def run_cli_here(argv: list[str], timeout_s: float) -> Outcome:
    """Run ``realistic_indoor.cli.main(argv)`` in this process, capturing its output."""
    out, err = io.StringIO(), io.StringIO()
    outcome = Outcome()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            with _alarm(timeout_s):
                from realistic_indoor.cli import main

                outcome.exit_code = main(argv)
        except SystemExit as e:
            outcome.exit_code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
            if isinstance(e.code, str):
                print(e.code, file=sys.stderr)
        except CaseTimeout:
            outcome.timed_out = True
        except KeyboardInterrupt:
            raise
        except BaseException:
            outcome.error = traceback.format_exc()
    outcome.stdout, outcome.stderr = out.getvalue(), err.getvalue()
    outcome.warned = any("warning:" in line for line in outcome.stderr.splitlines())
    return outcome


def _user_error_types() -> tuple[type[BaseException], ...]:
    import gymnasium

    from realistic_indoor.errors import RealisticIndoorError

    return (RealisticIndoorError, gymnasium.error.Error)


def run_api_here(call: ApiCall, ctx: Ctx, timeout_s: float) -> Outcome:
    """Run an API call in this process: a user error is a refusal, any other exception a crash."""
    outcome = Outcome()
    out, err = io.StringIO(), io.StringIO()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), _alarm(timeout_s):
                call(ctx)
            outcome.exit_code = 0
        except CaseTimeout:
            outcome.timed_out = True
        except KeyboardInterrupt:
            raise
        except BaseException as e:
            if isinstance(e, _user_error_types()):
                outcome.exit_code = 1
                outcome.stderr = f"{type(e).__name__}: {e}"
            else:
                outcome.error = traceback.format_exc()
    outcome.stdout = out.getvalue()
    outcome.warned = any(issubclass(w.category, Warning) for w in caught)
    return outcome


def _limit_memory(gigabytes: float) -> Callable[[], None]:
    def limit() -> None:
        size = int(gigabytes * (1 << 30))
        resource.setrlimit(resource.RLIMIT_AS, (size, size))

    return limit


def _child_env() -> dict[str, str]:
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONUNBUFFERED="1")
    env.pop("PYTHONWARNINGS", None)
    return env


def run_child(command: list[str], cwd: Path, timeout_s: float) -> subprocess.CompletedProcess | None:
    """Run ``command`` with a memory limit; ``None`` if it ran past ``timeout_s`` (it is killed)."""
    try:
        return subprocess.run(
            command,
            cwd=cwd,
            env=_child_env(),
            capture_output=True,
            text=True,
            errors="replace",
            timeout=timeout_s,
            preexec_fn=_limit_memory(CHILD_MEMORY_GB),
            check=False,
        )
    except subprocess.TimeoutExpired:
        return None


def run_cli_subprocess(argv: list[str], cwd: Path, timeout_s: float) -> Outcome:
    """Run ``python -m realistic_indoor.cli ARGV`` and read its real exit code."""
    done = run_child([sys.executable, "-m", "realistic_indoor.cli", *argv], cwd, timeout_s)
    if done is None:
        return Outcome(timed_out=True)
    outcome = Outcome(stdout=done.stdout, stderr=done.stderr)
    if done.returncode < 0:
        outcome.error = f"killed by signal {-done.returncode}"
    else:
        outcome.exit_code = done.returncode
    outcome.warned = any("warning:" in line for line in done.stderr.splitlines())
    return outcome


def run_in_child(case: Case, root: Path) -> Outcome:
    """Run ``case`` in this script in a child process, with a memory limit."""
    command = [sys.executable, str(Path(__file__).resolve()), "--run-case", case.name, "--root", str(root)]
    done = run_child(command, case_folder(root, case), case.timeout_s)
    if done is None:
        return Outcome(timed_out=True)
    last = done.stdout.strip().splitlines()[-1:] or [""]
    try:
        return Outcome(**json.loads(last[0]))
    except (json.JSONDecodeError, TypeError):
        why = f"killed by signal {-done.returncode}" if done.returncode < 0 else f"exit {done.returncode}"
        return Outcome(error=f"child died ({why}): {(done.stderr.strip().splitlines() or [''])[-1]}")


def execute(case: Case, ctx: Ctx) -> Outcome:
    """Run ``case`` in this process (CLI or API), in its folder."""
    with _inside(ctx.work):
        if case.call is not None:
            return run_api_here(case.call, ctx, case.timeout_s)
        return run_cli_here(expand(case.argv, ctx), case.timeout_s)


def case_folder(root: Path, case: Case) -> Path:
    """The folder ``case`` runs in."""
    return root / "cases" / re.sub(r"[^A-Za-z0-9._-]+", "_", case.name)


def run_case(case: Case, root: Path, keep: bool = False) -> dict[str, Any]:
    """Prepare, run and check one case; its result as a JSON-ready dict."""
    ctx = Ctx(root / "in", case_folder(root, case))
    ctx.work.mkdir(parents=True)
    for step in case.setup:
        step(ctx)
    before = snapshot((ctx.inputs, ctx.work))
    start = time.perf_counter()
    if case.run_in == "cli":
        outcome = run_cli_subprocess(expand(case.argv, ctx), ctx.work, case.timeout_s)
    elif case.run_in == "child":
        outcome = run_in_child(case, root)
    else:
        outcome = execute(case, ctx)
    outcome.seconds = time.perf_counter() - start
    outcome.changed, outcome.created = compare(
        before, snapshot((ctx.inputs, ctx.work)), ctx.work, case.outputs
    )
    problems = classify(case.expect, outcome)
    if not keep:
        _remove(ctx.work)
    return {
        "name": case.name,
        "category": case.category,
        "expect": case.expect,
        "run_in": case.run_in,
        "argv": expand(case.argv, ctx) if case.argv else None,
        "problems": problems,
        "message": error_line(outcome),
        **dataclasses.asdict(outcome),
    }


def error_line(out: Outcome) -> str:
    """The line that says what happened: the exception of a traceback, else the last error line."""
    for text in (out.error, out.stderr if TRACEBACK in out.stderr else ""):
        lines = [line for line in text.splitlines() if line.strip() and not line.startswith(" ")]
        if lines:
            return lines[-1].strip()
    if out.timed_out:
        return "timed out"
    lines = [line for line in out.stderr.splitlines() if line.strip()]
    others = [line for line in lines if not line.startswith(WARNING_PREFIX)]
    if out.exit_code == 0:
        warned = [line for line in lines if "warning:" in line]
        return f"exit 0: {(warned or out.stdout.strip().splitlines() or [''])[-1].strip()}"
    return f"exit {out.exit_code}: {(others or lines or [''])[-1].strip()}"


def _remove(folder: Path) -> None:
    for dirpath, _dirs, _files in os.walk(folder):
        with contextlib.suppress(OSError):
            os.chmod(dirpath, 0o755)
    shutil.rmtree(folder, ignore_errors=True)


# -- setup steps --------------------------------------------------------------------------------------


def copy(source: str, target: str | None = None) -> Setup:
    """Copy an input (a file or folder of the inputs) into the case folder."""

    def step(ctx: Ctx) -> None:
        src, dst = ctx.inputs / source, ctx.work / (target or Path(source).name)
        dst.parent.mkdir(parents=True, exist_ok=True)
        if src.is_dir():
            shutil.copytree(src, dst)
        else:
            shutil.copy2(src, dst)

    return step


def make_dir(path: str) -> Setup:
    """Create an empty folder in the case folder."""
    return lambda ctx: (ctx.work / path).mkdir(parents=True, exist_ok=True)


def symlink(target: str, link: str) -> Setup:
    """A symbolic link ``link`` -> ``target`` in the case folder."""
    return lambda ctx: os.symlink(target, ctx.work / link)


def hardlink(source: str, link: str) -> Setup:
    """A hard link ``link`` to the case folder's ``source``."""
    return lambda ctx: os.link(ctx.work / source, ctx.work / link)


def read_only(path: str) -> Setup:
    """A read-only folder in the case folder."""

    def step(ctx: Ctx) -> None:
        (ctx.work / path).mkdir(parents=True, exist_ok=True)
        os.chmod(ctx.work / path, 0o555)

    return step


def fifo(path: str) -> Setup:
    """A named pipe (reading it would block forever)."""
    return lambda ctx: os.mkfifo(ctx.work / path)


def write(path: str, text: str) -> Setup:
    """A text file in the case folder."""

    def step(ctx: Ctx) -> None:
        (ctx.work / path).parent.mkdir(parents=True, exist_ok=True)
        (ctx.work / path).write_text(text, encoding="utf-8")

    return step


def sparse_file(path: str, megabytes: int) -> Setup:
    """A file of ``megabytes`` of zeros that takes no disk space."""

    def step(ctx: Ctx) -> None:
        with (ctx.work / path).open("wb") as f:
            f.truncate(megabytes << 20)

    return step


def prior_evaluation(folder: str) -> Setup:
    """The result files of an earlier ``evaluate`` run in ``folder``."""
    record = {"task": {"agent": "random", "env": "HouseExplore-v0", "seed": 0}, "result": {}}
    files = {
        "episodes.jsonl": json.dumps(record) + "\n",
        "results.json": '{"results": [], "meta": {}}\n',
        "summary.csv": "agent,env\n",
    }

    def step(ctx: Ctx) -> None:
        for name, text in files.items():
            write(f"{folder}/{name}", text)(ctx)

    return step


# -- the API calls --------------------------------------------------------------------------------------


def _resolve(value: Any, ctx: Ctx) -> Any:
    """``@/`` in strings replaced by the inputs folder; ``@load:NAME`` becomes the loaded plan."""
    if isinstance(value, str):
        if value.startswith("@load:"):
            from realistic_indoor.io import load

            return load(ctx.inputs / value.removeprefix("@load:"))
        return value.replace("@/", f"{ctx.inputs}/")
    if isinstance(value, dict):
        return {k: _resolve(v, ctx) for k, v in value.items()}
    return value


def api_load(ctx: Ctx, name: str, **options: Any) -> object:
    """``realistic_indoor.io.load`` of an input."""
    from realistic_indoor.io import load

    return load(_resolve(name, ctx), **options)


def api_save(ctx: Ctx, target: str) -> object:
    """``realistic_indoor.io.save`` of the valid plan to ``target``."""
    from realistic_indoor.io import load, save

    return save(load(ctx.inputs / "house.json"), _resolve(target, ctx))


def api_episode(
    ctx: Ctx,
    env_id: str = "HouseExplore-v0",
    steps: int = 2,
    seed: Any = 0,
    options: dict | None = None,
    action: Any = None,
    reset: bool = True,
    **kwargs: Any,
) -> object:
    """``gymnasium.make(env_id, **kwargs)``, reset, and a few steps."""
    import gymnasium as gym

    import realistic_indoor.envs  # noqa: F401 - registers the ids

    env = gym.make(env_id, **{k: _resolve(v, ctx) for k, v in kwargs.items()})
    try:
        if reset:
            env.reset(seed=seed, options=_resolve(options, ctx))
        for _ in range(steps):
            env.step(env.action_space.sample() if action is None else action)
    finally:
        env.close()
    return env


def api_vector(ctx: Ctx, env_id: str = "HouseExplore-v0", num_envs: Any = 2, **kwargs: Any) -> object:
    """``gymnasium.make_vec(env_id, num_envs, **kwargs)``, reset, and a step."""
    import gymnasium as gym

    import realistic_indoor.envs  # noqa: F401 - registers the ids

    env = gym.make_vec(env_id, num_envs=num_envs, **{k: _resolve(v, ctx) for k, v in kwargs.items()})
    try:
        env.reset(seed=0)
        env.step(env.action_space.sample())
    finally:
        env.close()
    return env


def api_construct(ctx: Ctx, target: str, args: tuple[Any, ...] = (), **kwargs: Any) -> object:
    """Call ``module:name`` (a config class or factory) with ``args`` and the keywords."""
    module, _, name = target.partition(":")
    return getattr(importlib.import_module(module), name)(*args, **kwargs)


# -- the corpus -------------------------------------------------------------------------------------------


def _json_variant(change: Callable[[dict], Any]) -> Callable[[dict[str, bytes]], bytes]:
    def build(base: dict[str, bytes]) -> bytes:
        data = json.loads(base["house.json"])
        change(data)
        return json.dumps(data, indent=1).encode()

    return build


def _scaled(factor: float) -> Callable[[dict], None]:
    def change(data: dict) -> None:
        for room in data["rooms"]:
            room["outline"] = [[x * factor, y * factor] for x, y in room["outline"]]
        for door in data["doors"]:
            door["x"], door["y"] = door["x"] * factor, door["y"] * factor

    return change


def _text_variant(source: str, old: bytes, new: bytes) -> Callable[[dict[str, bytes]], bytes]:
    def build(base: dict[str, bytes]) -> bytes:
        if old not in base[source]:
            raise ValueError(f"corpus: {old!r} not found in {source}")
        return base[source].replace(old, new, 1)

    return build


def _model_variant(change: Callable[[dict], Any]) -> Callable[[dict[str, bytes]], bytes]:
    def build(base: dict[str, bytes]) -> bytes:
        data = json.loads(base["model.json"])
        change(data)
        return json.dumps(data, indent=1).encode()

    return build


def _first_room(**changes: Any) -> Callable[[dict], None]:
    return lambda data: data["rooms"][1].update(changes)


def _first_door(**changes: Any) -> Callable[[dict], None]:
    return lambda data: data["doors"][1].update(changes)


def _xml_variant(
    pattern: str, replacement: str, source: str = "house.xml"
) -> Callable[[dict[str, bytes]], bytes]:
    def build(base: dict[str, bytes]) -> bytes:
        text, n = re.subn(pattern, replacement, base[source].decode(), count=1, flags=re.S)
        if n != 1:
            raise ValueError(f"corpus: {pattern!r} not found in {source}")
        return text.encode()

    return build


def _world(
    depth: str, width: str, body: str = '<room name="small_1x1.t3d" x="0" y="0" theta="0" />'
) -> bytes:
    return f'<?xml version="1.0"?>\n<world depth="{depth}" width="{width}" name="w">\n  {body}\n</world>\n'.encode()


def _zip(members: dict[str, bytes]) -> bytes:
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as z:
        for name, data in members.items():
            z.writestr(zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0)), data)
    return buffer.getvalue()


_BOMB = (
    '<?xml version="1.0"?>\n<!DOCTYPE lolz [\n <!ENTITY lol "lol">\n'
    + "".join(
        f' <!ENTITY lol{i} "{("&lol" + (str(i - 1) if i > 1 else "") + ";") * 10}">\n' for i in range(1, 10)
    )
    + "]>\n<building><name>&lol9;</name></building>\n"
)

CORPUS_BASES = ("house.json", "house.xml", "small.wg.xml", "model.json")
"""Valid files written by the package once (a 60 m2 house, seed 1; a 5 x 5 random map; the default
office model); the hostile files are derived from them."""

CORPUS_BUILDERS: dict[str, Callable[[dict[str, bytes]], bytes]] = {
    # JSON plans
    "not_utf8.json": lambda b: b["house.json"].replace(b'"entrance"', '"entr\xe9e"'.encode("latin-1")),
    "no_rooms.json": _json_variant(lambda d: d.update(rooms=[], doors=[])),
    "nan_coords.json": _json_variant(lambda d: d["rooms"][1]["outline"][1].__setitem__(0, math.nan)),
    "infinity_coords.json": _json_variant(lambda d: d["rooms"][1]["outline"][1].__setitem__(0, math.inf)),
    "coords_1e300.json": _json_variant(_scaled(1e300)),
    "huge_coords.json": _json_variant(_scaled(1e6)),
    "door_unknown_room.json": _json_variant(_first_door(rooms=["r0", "r99"])),
    "door_nan_width.json": _json_variant(_first_door(width_m=math.nan)),
    "door_negative_width.json": _json_variant(_first_door(width_m=-1.0)),
    "bowtie.json": _json_variant(_first_room(outline=[[0, 0], [4.1, 4.3], [4.1, 0], [0, 4.3]])),
    "two_vertices.json": _json_variant(_first_room(outline=[[0, 0], [4.1, 4.3]])),
    "duplicate_room_ids.json": _json_variant(lambda d: d["rooms"][2].update(id=d["rooms"][1]["id"])),
    "unknown_label.json": _json_variant(_first_room(label="ballroom")),
    "unknown_type.json": _json_variant(lambda d: d.update(building_type="castle")),
    "outline_string.json": _json_variant(_first_room(outline="abc")),
    "rooms_not_list.json": _json_variant(lambda d: d.update(rooms=5)),
    "door_nan_angle.json": _json_variant(_first_door(angle_rad=math.nan)),
    "coords_bigint.json": _text_variant("house.json", b"4.1", b"1" + b"0" * 400),
    "coords_5000_digits.json": _text_variant("house.json", b"4.1", b"1" + b"0" * 5000),
    "metadata_string.json": _json_variant(lambda d: d.update(metadata="abc")),
    "room_id_list.json": _json_variant(_first_room(id=["r", 1])),
    "label_null.json": _json_variant(_first_room(label=None)),
    "version_string.json": _json_variant(lambda d: d.update(version="1")),
    "wrong_schema.json": lambda b: b'{"schema": "something-else", "version": 1}\n',
    "json_array.json": lambda b: b"[1, 2, 3]\n",
    "deep_nesting.json": lambda b: b"[" * 10000 + b"]" * 10000,
    "empty.json": lambda b: b"",
    "binary.json": lambda b: bytes(range(256)) * 4,
    "plan.txt": lambda b: b["house.json"],
    # floor-plan XML
    "truncated.xml": lambda b: b["house.xml"][: len(b["house.xml"]) // 2],
    "entity_bomb.xml": lambda b: _BOMB.encode(),
    "external_entity.xml": lambda b: (
        b'<?xml version="1.0"?>\n<!DOCTYPE building [<!ENTITY x SYSTEM "file:///etc/passwd">]>\n'
        b"<building><name>&x;</name></building>\n"
    ),
    "empty.xml": lambda b: b"",
    "not_xml.xml": lambda b: b"hello, I am not XML\n",
    "scale_nan.xml": _xml_variant(r"(<real_distance>\s*<value>)100(</value>)", r"\1nan\2"),
    "scale_inf.xml": _xml_variant(r"(<real_distance>\s*<value>)100(</value>)", r"\1inf\2"),
    "scale_zero.xml": _xml_variant(r"(<real_distance>\s*<value>)100(</value>)", r"\g<1>0\2"),
    "scale_zero_pixels.xml": _xml_variant(r"(<represented_distance>\s*<value>)100(</value>)", r"\g<1>0\2"),
    "scale_negative.xml": _xml_variant(r"(<real_distance>\s*<value>)100(</value>)", r"\1-100\2"),
    "scale_missing.xml": _xml_variant(r"\s*<scale>.*?</scale>", ""),
    "scale_unit_unknown.xml": _xml_variant(r"<um>cm</um>", "<um>parsec</um>"),
    "point_nan.xml": _xml_variant(r'(<bounding_polygon>\s*<point x=")\d+', r"\1nan"),
    "duplicate_space_ids.xml": _xml_variant(r'<space id="r1">', '<space id="r0">'),
    "portal_unknown_space.xml": _xml_variant(r"<id>r5</id>", "<id>nosuch</id>"),
    "space_no_polygon.xml": _xml_variant(r"<bounding_polygon>.*?</bounding_polygon>", ""),
    "utf16.xml": lambda b: b["house.xml"].decode().replace("UTF-8", "UTF-16").encode("utf-16"),
    # World Generator XML
    "grid_20000.wg.xml": lambda b: _world("20000", "20000"),
    "grid_100000.wg.xml": lambda b: _world("100000", "100000"),
    "grid_negative.wg.xml": lambda b: _world("-5", "5"),
    "grid_zero.wg.xml": lambda b: _world("0", "0"),
    "grid_nan.wg.xml": lambda b: _world("nan", "5"),
    "module_outside.wg.xml": lambda b: _world(
        "5", "5", '<room name="small_1x1.t3d" x="10" y="10" theta="0" />'
    ),
    "unknown_module.wg.xml": lambda b: _world("5", "5", '<room name="nosuch.t3d" x="0" y="0" theta="0" />'),
    "theta_text.wg.xml": lambda b: _world("5", "5", '<room name="small_1x1.t3d" x="0" y="0" theta="abc" />'),
    "depth_float.wg.xml": lambda b: _world("1e3", "5"),
    "door_direction_bad.wg.xml": _text_variant("small.wg.xml", b'direction="1"', b'direction="7"'),
    # building-type models (generate --model)
    "model_nan_area.json": _model_variant(lambda d: d["labels"]["corridor"].update(area_mean=math.nan)),
    "model_huge_area.json": _model_variant(lambda d: d["labels"]["corridor"].update(area_mean=1e300)),
    "model_negative_share.json": _model_variant(lambda d: d["labels"]["corridor"].update(share=-1.0)),
    "model_zero_shares.json": _model_variant(lambda d: [v.update(share=0.0) for v in d["labels"].values()]),
    "model_labels_list.json": _model_variant(lambda d: d.update(labels=[1, 2])),
    # model files
    "not_a_zip.zip": lambda b: b"this is not a zip file\n",
    "zip_without_model.zip": lambda b: _zip({"readme.txt": b"no model in here\n"}),
    "zip_bad_data.zip": lambda b: _zip({"data": b"{not json", "pytorch_variables.pth": b"garbage"}),
    "empty.zip": lambda b: b"",
}
"""Hostile files of ``tests/data/hostile/``: name -> builder from the bases' bytes."""

PLAN_READERS = ("info", "validate", "render", "convert", "evaluate", "load", "env")
HOSTILE_PLANS: dict[str, str | dict[str, str]] = {
    "not_utf8.json": "refuse",
    "no_rooms.json": {"info": "handled", "convert": "handled", "load": "handled", "*": "refuse"},
    "nan_coords.json": "refuse",
    "infinity_coords.json": "refuse",
    "coords_1e300.json": "refuse",
    "huge_coords.json": {"render": "handled", "evaluate": "refuse", "env": "refuse", "*": "handled"},
    "door_unknown_room.json": "refuse",
    "door_nan_width.json": "refuse",
    "door_negative_width.json": "refuse",
    "bowtie.json": "handled",
    "two_vertices.json": "refuse",
    "duplicate_room_ids.json": "refuse",
    "unknown_label.json": "refuse",
    "unknown_type.json": "refuse",
    "outline_string.json": "refuse",
    "rooms_not_list.json": "refuse",
    "door_nan_angle.json": "refuse",
    "coords_bigint.json": "refuse",
    "coords_5000_digits.json": "refuse",
    "metadata_string.json": "refuse",
    "room_id_list.json": "refuse",
    "label_null.json": "refuse",
    "version_string.json": "refuse",
    "wrong_schema.json": "refuse",
    "json_array.json": "refuse",
    "deep_nesting.json": "refuse",
    "empty.json": "refuse",
    "binary.json": "refuse",
    "plan.txt": "refuse",
    "truncated.xml": "refuse",
    "entity_bomb.xml": "refuse",
    "external_entity.xml": "refuse",
    "empty.xml": "refuse",
    "not_xml.xml": "refuse",
    "scale_nan.xml": "refuse",
    "scale_inf.xml": "refuse",
    "scale_zero.xml": "refuse",
    "scale_zero_pixels.xml": "refuse",
    "scale_negative.xml": "refuse",
    "scale_missing.xml": "handled",
    "scale_unit_unknown.xml": "refuse",
    "point_nan.xml": "refuse",
    "duplicate_space_ids.xml": "handled",
    "portal_unknown_space.xml": "handled",
    "space_no_polygon.xml": "handled",
    "utf16.xml": "any",
    "real_scale_nan.xml": "refuse",
    "real_scale_missing.xml": "handled",
    "grid_20000.wg.xml": "refuse",
    "grid_100000.wg.xml": "refuse",
    "grid_negative.wg.xml": "refuse",
    "grid_zero.wg.xml": "refuse",
    "grid_nan.wg.xml": "refuse",
    "module_outside.wg.xml": "refuse",
    "unknown_module.wg.xml": "refuse",
    "theta_text.wg.xml": "refuse",
    "depth_float.wg.xml": "refuse",
    "door_direction_bad.wg.xml": "handled",
    "many_rooms.json": "any",
    "zip_without_model.zip": "refuse",
    "hostile_set/": "refuse",
    "missing.json": "refuse",
}
"""Plan inputs given to every plan reader, with the expectation (per reader where it differs);
``hostile_set/`` is a folder passed as a plan."""
IN_CHILD = {"grid_20000.wg.xml"}
"""Inputs that may allocate gigabytes: their cases run in a child process with a memory limit."""


def write_corpus(folder: Path = CORPUS) -> list[Path]:
    """Write the hostile files of :data:`CORPUS_BUILDERS` into ``folder`` from its bases."""
    bases = {name: (folder / name).read_bytes() for name in CORPUS_BASES}
    written = []
    for name, build in CORPUS_BUILDERS.items():
        (folder / name).write_bytes(build(bases))
        written.append(folder / name)
    return written


def build_inputs(root: Path) -> Path:
    """Fill ``root/in`` with the corpus, copies of a few real plans and derived sets; return it."""
    inputs = root / "in"
    shutil.copytree(CORPUS, inputs)
    real = inputs / "real"
    real.mkdir()
    for pick in REAL_PICKS:
        source = REAL_PLANS / pick
        if source.is_dir():
            plans = sorted(source.glob("*.xml"), key=lambda p: p.stat().st_size)[:1]
        else:
            plans = [source] if source.is_file() else []
        for plan in plans:
            shutil.copy(plan, real / plan.name)
    base = next(iter(sorted(real.glob("*.xml"))), inputs / "house.xml")
    text = base.read_text(encoding="utf-8")
    nan_scale = re.sub(r"(<real_distance>\s*<value>)[^<]*(</value>)", r"\1nan\2", text, count=1)
    (inputs / "real_scale_nan.xml").write_text(nan_scale, encoding="utf-8")
    (inputs / "real_scale_missing.xml").write_text(
        re.sub(r"<scale>.*?</scale>", "", text, flags=re.S), encoding="utf-8"
    )
    for folder, names in {
        "mixed": ("house.json", "small.wg.xml", "binary.json", "truncated.xml"),
        "hostile_set": ("binary.json", "empty.json", "truncated.xml", "not_utf8.json"),
        "good_set": ("house.json", "small.wg.xml"),
    }.items():
        (inputs / folder).mkdir()
        for name in names:
            shutil.copy(inputs / name, inputs / folder / name)
    (inputs / "empty_dir").mkdir()
    (inputs / "many_rooms.json").write_text(_many_rooms(40, 50), encoding="utf-8")
    return inputs


def _many_rooms(columns: int, rows: int) -> str:
    """A JSON plan of ``columns x rows`` rooms of 2 m x 2 m, each with a door to its right neighbour."""
    data = json.loads((CORPUS / "house.json").read_text(encoding="utf-8"))
    rooms, doors = [], []
    for i in range(columns):
        for j in range(rows):
            x, y = 2.0 * i, 2.0 * j
            outline = [[x, y], [x + 2, y], [x + 2, y + 2], [x, y + 2]]
            rooms.append({"id": f"r{i}_{j}", "label": "small", "function": "closet", "outline": outline})
            if i:
                doors.append(
                    {
                        "id": f"d{i}_{j}",
                        "rooms": [f"r{i - 1}_{j}", f"r{i}_{j}"],
                        "x": x,
                        "y": y + 1,
                        "width_m": 0.8,
                        "angle_rad": math.pi / 2,
                    }
                )
    data.update(rooms=rooms, doors=doors)
    return json.dumps(data)


# -- the cases ------------------------------------------------------------------------------------------------

EV = "--episodes 1 --max-steps 5 --workers 1 --out ev --no-figures --quiet"
"""The tail of a short ``evaluate`` run: one 5-step episode in this process."""
TRAIN = "train --preset smoke --out m.zip --workers 1 --quiet"
"""The start of a ``train`` run: every train case must be refused before training starts."""
NO_TRAIN = f"{TRAIN} --no-train --eval-episodes 1 --eval-max-steps 5"
HOUSE = "generate --type house --seed 1"
NUMERIC_VALUES = ("-1", "0", "nan", "inf", "1e308", "abc")


def _cli(name: str, expect: str, command: str, *setup: Setup, outputs: str = "", **more: Any) -> Case:
    """A command case: ``name`` starts with the verb, ``command`` is split as a shell would."""
    return Case(
        name,
        name.split("/")[0],
        expect,
        tuple(shlex.split(command)),
        None,
        setup,
        tuple(outputs.split()),
        **more,
    )


def _api(what: str, expect: str, call: ApiCall, *setup: Setup, outputs: str = "", **more: Any) -> Case:
    """An API case."""
    return Case(f"api/{what}", "api", expect, (), call, setup, tuple(outputs.split()), **more)


def _ev(agents: str = "random", envs: str = "HouseExplore-v0", more: str = "") -> str:
    """An ``evaluate`` command of one short episode."""
    return f"evaluate --agents {shlex.quote(agents)} --envs {shlex.quote(envs)} {EV} {more}"


def _reader_case(plan: str, reader: str, expect: str) -> Case:
    """``plan`` (a file of the inputs, or ``@/``: a folder) given to one plan reader."""
    path = f"@/{plan}"
    label = plan.rstrip("/")
    more: dict[str, Any] = {"run_in": "child"} if plan in IN_CHILD else {}
    outputs = "report.txt out.png out.json ev"
    if reader == "load":
        return _api(
            f"plan/{label}/load", expect, functools.partial(api_load, name=path), outputs=outputs, **more
        )
    if reader == "env":
        call = functools.partial(api_episode, plan_path=path)
        return _api(f"plan/{label}/env", expect, call, outputs=outputs, **more)
    command = {
        "info": f"info {path}",
        "validate": f"validate {path} -o report.txt",
        "render": f"render {path} -o out.png",
        "convert": f"convert {path} -o out.json",
        "evaluate": _ev(envs=f"HouseExplore-v0:{path}"),
    }[reader]
    return _cli(f"{reader}/plan/{label}", expect, command, outputs=outputs, **more)


def plan_cases() -> list[Case]:
    """Every hostile plan through every plan reader."""
    cases = []
    for plan, expectation in HOSTILE_PLANS.items():
        for reader in PLAN_READERS:
            if plan.endswith(".zip") and reader != "load":
                continue
            expect = (
                expectation if isinstance(expectation, str) else expectation.get(reader, expectation["*"])
            )
            cases.append(_reader_case(plan, reader, expect))
    return cases


NUMERIC_OPTIONS: tuple[tuple[str, str, dict[str, str], str], ...] = (
    # option, command without it, expectations of the values not refused (or extra values), outputs
    ("--seed", "validate @/house.json --quiet -o r.txt", {"0": "accept"}, "r.txt"),
    ("--worst", "validate @/house.json -o r.txt", {"0": "accept"}, "r.txt"),
    ("--dpi", "render @/house.json -o out.png", {"100000": "refuse"}, "out.png"),
    ("--size", "render @/house.json -o out.png", {"100000": "refuse"}, "out.png"),
    ("--resolution", "convert @/house.json -o out.yaml", {"1e-7": "refuse"}, "out.*"),
    ("--wall-height", "convert @/house.json -o out.sdf", {}, "out.sdf"),
    ("--wall-thickness", "convert @/house.json -o out.sdf", {"100": "refuse"}, "out.sdf"),
    ("--door-height", "convert @/house.json -o out.sdf", {}, "out.sdf"),
    ("--area", f"{HOUSE} -o out.json", {"1e9": "refuse"}, "out.json"),
    ("--seed", "generate --type house -o out.json", {"0": "accept", str(2**70): "any"}, "out.json"),
    ("--count", f"{HOUSE} --out-dir out", {}, "out"),
    (
        "--width",
        "generate --type random --seed 1 --height 5 -o out.wg.xml",
        {"100000": "refuse"},
        "out.wg.xml",
    ),
    (
        "--height",
        "generate --type random --seed 1 --width 5 -o out.wg.xml",
        {"100000": "refuse"},
        "out.wg.xml",
    ),
    ("--wall-height", f"{HOUSE} -o out.sdf", {}, "out.sdf"),
    ("--wall-thickness", f"{HOUSE} -o out.sdf", {"100": "refuse"}, "out.sdf"),
    ("--door-height", f"{HOUSE} -o out.sdf", {}, "out.sdf"),
    (
        "--episodes",
        "evaluate --agents random --envs HouseExplore-v0 --max-steps 5 --workers 1 --out ev",
        {},
        "ev",
    ),
    ("--seed", _ev(), {"0": "accept"}, "ev"),
    (
        "--workers",
        "evaluate --agents random --envs HouseExplore-v0 --episodes 1 --max-steps 5 --out ev",
        {},
        "ev",
    ),
    (
        "--max-steps",
        "evaluate --agents random --envs HouseExplore-v0 --episodes 1 --workers 1 --out ev",
        {},
        "ev",
    ),
    ("--timesteps", TRAIN, {}, ""),
    ("--n-envs", TRAIN, {}, ""),
    ("--seed", TRAIN, {"0": "skip"}, ""),
    ("--eval-episodes", TRAIN, {"0": "skip"}, ""),
    ("--eval-max-steps", TRAIN, {}, ""),
    ("--workers", TRAIN, {}, ""),
)
"""Numeric options of every verb, each given :data:`NUMERIC_VALUES` (refused unless said otherwise)
and the extra values of its expectations; ``skip`` marks a value that would start a long run (a
train case must be refused before training starts)."""


def numeric_cases() -> list[Case]:
    """Every numeric option with negative, zero, NaN, infinite, huge and non-numeric values."""
    cases = []
    for option, command, special, outputs in NUMERIC_OPTIONS:
        verb = command.split()[0]
        for value in dict.fromkeys((*NUMERIC_VALUES, *special)):
            expect = special.get(value, "refuse")
            if expect != "skip":
                name = f"{verb}/option/{option.lstrip('-')}={value}"
                cases.append(_cli(name, expect, f"{command} {option} {value}", outputs=outputs))
    return cases


def info_cases() -> list[Case]:
    """``info`` on odd files: pipes, links, unknown endings, real plans; a few in a subprocess."""
    return [
        _cli("info/accept/house.json", "accept", "info @/house.json"),
        _cli("info/accept/house.xml", "accept", "info @/house.xml --check"),
        _cli("info/accept/small.wg.xml", "accept", "info @/small.wg.xml"),
        _cli("info/accept/real-plan", "accept", "info @/real/Milano-1.xml --infer-entrances"),
        _cli("info/strict-real-plan", "any", "info @/real/Milano-1.xml --strict"),
        _cli("info/fifo.json", "refuse", "info pipe.json", fifo("pipe.json"), timeout_s=20),
        _cli("info/symlink-loop.json", "refuse", "info loop.json", symlink("loop.json", "loop.json")),
        _cli("info/dangling-link.json", "refuse", "info gone.json", symlink("nowhere.json", "gone.json")),
        _cli("info/no-extension", "refuse", "info plan", copy("house.json", "plan")),
        _cli("info/writable-only.png", "refuse", "info plan.png", copy("house.json", "plan.png")),
        _cli("info/upper-case-ending", "any", "info PLAN.JSON", copy("house.json", "PLAN.JSON")),
        _cli("info/two-plans", "refuse", "info @/house.json @/house.xml"),
        _cli("info/huge-file.json", "refuse", "info big.json", sparse_file("big.json", 300)),
        _cli("info/subprocess/not_utf8", "refuse", "info @/not_utf8.json", run_in="cli"),
        _cli("info/subprocess/accept", "accept", "info @/house.json", run_in="cli"),
        _cli("info/subprocess/grid_100000", "refuse", "info @/grid_100000.wg.xml", run_in="cli"),
    ]


def validate_cases() -> list[Case]:
    """``validate``: outputs that are inputs, empty sets, bad references."""
    plan = copy("house.json", "plan.json")
    in_set = (copy("house.json", "set/plan.json"), copy("small.wg.xml", "set/small.wg.xml"))
    precious = (copy("small.wg.xml", "precious.txt"), symlink("precious.txt", "r.txt"))
    return [
        _cli("validate/accept/report", "accept", "validate @/house.json -o r.txt", outputs="r.txt"),
        _cli(
            "validate/accept/json", "accept", "validate @/good_set --format json -o r.json", outputs="r.json"
        ),
        _cli("validate/output-is-input-in-set", "refuse", "validate set -o set/plan.json", *in_set),
        _cli("validate/output-is-input", "refuse", "validate plan.json -o plan.json", plan),
        _cli("validate/plot-is-input", "refuse", "validate set --plot set/plan.json", *in_set),
        _cli(
            "validate/output-symlink-to-input",
            "refuse",
            "validate plan.json -o link.txt",
            plan,
            symlink("plan.json", "link.txt"),
        ),
        _cli(
            "validate/output-hardlink-to-input",
            "refuse",
            "validate plan.json -o hard.txt",
            plan,
            hardlink("plan.json", "hard.txt"),
        ),
        _cli(
            "validate/output-symlink-to-other-file",
            "accept",
            "validate @/house.json -o r.txt --overwrite",
            *precious,
            outputs="r.txt",
        ),
        _cli("validate/output-exists", "refuse", "validate @/house.json -o r.txt", write("r.txt", "mine\n")),
        _cli("validate/empty-folder", "refuse", "validate @/empty_dir"),
        _cli("validate/glob-matching-nothing", "refuse", "validate '@/nomatch*.json'"),
        _cli("validate/all-plans-bad", "refuse", "validate @/hostile_set"),
        _cli("validate/corpus-folder", "repair", "validate @/ --type office -o r.txt", outputs="r.txt"),
        _cli("validate/corpus-folder-mixed-types", "refuse", "validate @/ -o r.txt"),
        _cli("validate/some-plans-bad", "repair", "validate @/mixed"),
        _cli("validate/some-plans-bad-strict", "refuse", "validate @/mixed --strict"),
        _cli("validate/unknown-type", "refuse", "validate @/house.json --type castle"),
        _cli("validate/too-many-labels", "refuse", "validate @/house.json --labels a,b"),
        _cli("validate/empty-labels", "refuse", "validate @/house.json --labels ''"),
        _cli("validate/reference-missing", "refuse", "validate @/house.json --reference nosuch"),
        _cli("validate/reference-empty-folder", "refuse", "validate @/house.json --reference @/empty_dir"),
        _cli("validate/reference-binary", "refuse", "validate @/house.json --reference @/binary.json"),
        _cli(
            "validate/two-sample-features-unknown",
            "refuse",
            "validate @/good_set --quiet --two-sample-features nosuch",
        ),
        _cli("validate/output-inside-a-file", "refuse", "validate @/house.json -o @/house.json/r.txt"),
        _cli("validate/plot-inside-a-file", "refuse", "validate @/house.json --plot @/house.json/p.png"),
        _cli("validate/plot-unknown-ending", "refuse", "validate @/house.json --plot p.foo"),
        _cli("validate/output-is-folder", "refuse", "validate @/house.json -o out", make_dir("out")),
        _cli(
            "validate/read-only-folder",
            READ_ONLY_EXPECT,
            "validate @/house.json -o ro/r.txt",
            read_only("ro"),
            outputs="ro/r.txt",
        ),
        _cli("validate/subprocess/worst=abc", "refuse", "validate @/house.json --worst abc", run_in="cli"),
    ]


def render_cases() -> list[Case]:
    """``render``: outputs that are inputs or cannot be written."""
    return [
        _cli("render/accept/png", "accept", "render @/house.json -o out.png", outputs="out.png"),
        _cli(
            "render/accept/svg", "accept", "render @/small.wg.xml -o out.svg --functions", outputs="out.svg"
        ),
        _cli(
            "render/output-is-input",
            "refuse",
            "render plan.json -o plan.json",
            copy("house.json", "plan.json"),
        ),
        _cli("render/output-exists", "refuse", "render @/house.json -o out.png", write("out.png", "mine\n")),
        _cli("render/output-unknown-ending", "refuse", "render @/house.json -o out.jpg"),
        _cli("render/output-inside-a-file", "refuse", "render @/house.json -o @/house.json/out.png"),
        _cli("render/output-is-folder", "refuse", "render @/house.json -o out.png", make_dir("out.png")),
        _cli("render/folder-without-out-dir", "refuse", "render @/good_set -o out.png"),
        _cli("render/out-dir-inside-a-file", "refuse", "render @/good_set --out-dir @/house.json/pics"),
        _cli("render/out-dir-all-plans-bad", "refuse", "render @/hostile_set --out-dir pics"),
        _cli("render/out-dir-some-plans-bad", "repair", "render @/mixed --out-dir pics", outputs="pics"),
        _cli(
            "render/read-only-folder",
            READ_ONLY_EXPECT,
            "render @/house.json -o ro/out.png",
            read_only("ro"),
            outputs="ro/out.png",
        ),
        _cli("render/subprocess/entity-bomb", "refuse", "render @/entity_bomb.xml -o out.png", run_in="cli"),
    ]


def convert_cases() -> list[Case]:
    """``convert``: the output is the input (itself, a symlink, a hard link, the same folder)."""
    plan = copy("house.json", "plan.json")
    precious = copy("small.wg.xml", "precious.json")
    return [
        _cli("convert/accept/xml", "accept", "convert @/house.json -o out.xml", outputs="out.xml"),
        _cli("convert/accept/ros", "accept", "convert @/house.json -o out.yaml", outputs="out.*"),
        _cli("convert/accept/glb", "accept", "convert @/house.xml -o out.glb", outputs="out.glb"),
        _cli("convert/lossy-wg", "any", "convert @/house.json -o out.wg.xml", outputs="out.wg.xml"),
        _cli(
            "convert/output-is-input.xml",
            "refuse",
            "convert plan.xml -o plan.xml",
            copy("house.xml", "plan.xml"),
        ),
        _cli("convert/output-is-input.json", "refuse", "convert plan.json -o plan.json", plan),
        _cli(
            "convert/output-is-input-other-spelling",
            "refuse",
            "convert plan.json -o ./sub/../plan.json",
            plan,
            make_dir("sub"),
        ),
        _cli(
            "convert/output-symlink-to-input",
            "refuse",
            "convert plan.json -o link.json",
            plan,
            symlink("plan.json", "link.json"),
        ),
        _cli(
            "convert/output-hardlink-to-input",
            "refuse",
            "convert plan.json -o hard.json",
            plan,
            hardlink("plan.json", "hard.json"),
        ),
        _cli(
            "convert/input-symlink-output-target",
            "refuse",
            "convert link.json -o plan.json",
            plan,
            symlink("plan.json", "link.json"),
        ),
        _cli(
            "convert/output-symlink-to-other-file",
            "accept",
            "convert @/house.json -o link.json --overwrite",
            precious,
            symlink("precious.json", "link.json"),
            outputs="link.json",
        ),
        _cli(
            "convert/output-hardlink-of-other-file",
            "accept",
            "convert @/house.json -o hard.json --overwrite",
            precious,
            hardlink("precious.json", "hard.json"),
            outputs="hard.json",
        ),
        _cli(
            "convert/out-dir-is-input-folder",
            "refuse",
            "convert set --out-dir set --format json",
            copy("house.json", "set/plan.json"),
        ),
        _cli(
            "convert/out-dir-holds-outputs",
            "any",
            "convert set --out-dir out --format json",
            copy("house.json", "set/plan.json"),
            copy("small.wg.xml", "out/plan.json"),
            outputs="out/*",
        ),
        _cli(
            "convert/output-exists", "refuse", "convert @/house.json -o out.json", write("out.json", "mine\n")
        ),
        _cli("convert/output-unknown-ending", "refuse", "convert @/house.json -o out.foo"),
        _cli("convert/output-no-ending", "refuse", "convert @/house.json -o out"),
        _cli("convert/output-inside-a-file", "refuse", "convert @/house.json -o @/house.json/out.json"),
        _cli("convert/output-is-folder", "refuse", "convert @/house.json -o out.json", make_dir("out.json")),
        _cli("convert/folder-without-out-dir", "refuse", "convert @/good_set -o out.json"),
        _cli(
            "convert/out-dir-some-plans-bad",
            "repair",
            "convert @/mixed --out-dir out --format json",
            outputs="out",
        ),
        _cli("convert/out-dir-all-plans-bad", "refuse", "convert @/hostile_set --out-dir out --format json"),
        _cli(
            "convert/read-only-folder",
            READ_ONLY_EXPECT,
            "convert @/house.json -o ro/out.json",
            read_only("ro"),
            outputs="ro/out.json",
        ),
        _cli("convert/huge-coords-to-ros", "refuse", "convert @/huge_coords.json -o out.yaml"),
        _cli(
            "convert/huge-coords-to-png",
            "handled",
            "convert @/huge_coords.json -o out.png",
            outputs="out.png",
        ),
        _cli(
            "convert/huge-coords-to-glb",
            "handled",
            "convert @/huge_coords.json -o out.glb",
            outputs="out.glb",
        ),
        _cli(
            "convert/real-plan-to-ros-at-1mm",
            "refuse",
            "convert @/real/Milano-1.xml -o out.yaml --resolution 0.001",
            run_in="child",
        ),
        _cli(
            "convert/door-higher-than-walls",
            "any",
            "convert @/house.json -o out.sdf --wall-height 2 --door-height 3",
            outputs="out.sdf",
        ),
    ]


def generate_cases() -> list[Case]:
    """``generate``: folders with plans already, bad models, outputs that cannot be written."""
    existing = (copy("house.json", "maps/house_1.json"), copy("house.xml", "maps/house_2.xml"))
    office = "generate --type office --area 300 --seed 1 -o out.json --model"
    cases = [
        _cli("generate/accept/json", "accept", f"{HOUSE} -o out.json --png out.png", outputs="out.*"),
        _cli(
            "generate/accept/random-wg",
            "accept",
            "generate --type random --seed 1 --width 5 --height 5 -o out.wg.xml",
            outputs="out.wg.xml",
        ),
        _cli(
            "generate/count-into-folder-with-same-names",
            "refuse",
            f"{HOUSE} --count 2 --out-dir maps",
            *existing,
        ),
        _cli(
            "generate/count-into-folder-overwrite",
            "accept",
            f"{HOUSE} --count 2 --out-dir maps --overwrite",
            *existing,
            outputs="maps/*",
        ),
        _cli(
            "generate/count-into-folder-other-names",
            "accept",
            f"{HOUSE} --count 2 --out-dir maps",
            copy("house.json", "maps/mine.json"),
            outputs="maps/house_*",
        ),
        _cli(
            "generate/count-overwrite-through-symlink",
            "accept",
            f"{HOUSE} --count 2 --out-dir maps --overwrite",
            copy("house.xml", "precious.xml"),
            make_dir("maps"),
            symlink("../precious.xml", "maps/house_1.json"),
            outputs="maps/*",
        ),
        _cli("generate/output-exists-as-folder", "refuse", f"{HOUSE} -o out.json", make_dir("out.json")),
        _cli("generate/output-inside-a-file", "refuse", f"{HOUSE} -o @/house.json/out.json"),
        _cli("generate/png-inside-a-file", "refuse", f"{HOUSE} -o out.json --png @/house.json/out.png"),
        _cli("generate/out-dir-inside-a-file", "refuse", f"{HOUSE} --count 2 --out-dir @/house.json/maps"),
        _cli("generate/output-exists", "refuse", f"{HOUSE} -o out.json", write("out.json", "mine\n")),
        _cli(
            "generate/png-exists", "refuse", f"{HOUSE} -o out.json --png out.png", write("out.png", "mine\n")
        ),
        _cli("generate/output-unknown-ending", "refuse", f"{HOUSE} -o out.foo"),
        _cli("generate/png-not-a-picture", "refuse", f"{HOUSE} -o out.json --png out.json.txt"),
        _cli("generate/png-is-output", "refuse", f"{HOUSE} -o out.png --png out.png"),
        _cli("generate/count-format-unknown", "refuse", f"{HOUSE} --count 1 --out-dir maps --format foo"),
        _cli("generate/count-with-png", "refuse", f"{HOUSE} --count 2 --out-dir maps --png x.png"),
        _cli("generate/count-without-out-dir", "refuse", f"{HOUSE} --count 2 -o x.json"),
        _cli("generate/no-output", "any", HOUSE, outputs="*"),
        _cli(
            "generate/grid-100000",
            "refuse",
            "generate --type random --width 100000 --height 100000 -o out.wg.xml",
        ),
        _cli("generate/grid-on-house", "refuse", f"{HOUSE} --width 5 --height 5 -o out.json"),
        _cli("generate/model-accept", "accept", f"{office} @/model.json", outputs="out.json"),
        _cli("generate/model-binary", "refuse", f"{office} @/binary.json"),
        _cli("generate/model-not-utf8", "refuse", f"{office} @/not_utf8.json"),
        _cli("generate/model-wrong-schema", "refuse", f"{office} @/wrong_schema.json"),
        _cli("generate/model-a-plan", "refuse", f"{office} @/house.json"),
        _cli("generate/model-folder", "refuse", f"{office} @/"),
        _cli("generate/model-missing", "refuse", f"{office} nosuch.json"),
        _cli("generate/model-on-house", "refuse", f"{HOUSE} --model paper -o out.json"),
        _cli("generate/layout-on-house", "refuse", f"{HOUSE} --layout wings -o out.json"),
        _cli("generate/unknown-type", "refuse", "generate --type castle -o out.json"),
        _cli("generate/like-empty-folder", "refuse", "generate --like @/empty_dir --out-dir twins"),
        _cli("generate/like-binary", "refuse", "generate --like @/binary.json --out-dir twins"),
        _cli("generate/like-all-bad", "refuse", "generate --like @/hostile_set --out-dir twins"),
        _cli("generate/like-without-out-dir", "refuse", "generate --like @/good_set"),
        _cli(
            "generate/like-some-bad",
            "repair",
            "generate --like @/mixed --out-dir twins --seed 1",
            outputs="twins",
        ),
        _cli(
            "generate/like-into-its-own-folder",
            "any",
            "generate --like set --out-dir set --seed 1",
            copy("house.json", "set/house.json"),
            outputs="set/*",
        ),
        _cli(
            "generate/read-only-folder",
            READ_ONLY_EXPECT,
            f"{HOUSE} -o ro/out.json",
            read_only("ro"),
            outputs="ro/out.json",
        ),
    ]
    bad_models = ("nan_area", "huge_area", "negative_share", "zero_shares", "labels_list")
    return cases + [_cli(f"generate/model-{m}", "refuse", f"{office} @/model_{m}.json") for m in bad_models]


EVALUATE_AGENTS = {
    "unknown": "nosuch",
    "empty": "",
    "commas": ",,,",
    "one-unknown": "random,nosuch",
    "ppo-not-a-zip": "ppo:@/not_a_zip.zip",
    "ppo-zip-without-model": "ppo:@/zip_without_model.zip",
    "ppo-bad-data-zip": "ppo:@/zip_bad_data.zip",
    "ppo-empty-zip": "ppo:@/empty.zip",
    "ppo-missing": "ppo:nosuch.zip",
    "ppo-no-path": "ppo:",
    "ppo-a-plan": "ppo:@/house.json",
    "ppo-folder": "ppo:@/",
    "learned-not-a-zip": "learned:@/not_a_zip.zip",
    "learned-zip-without-model": "learned:@/zip_without_model.zip",
    "learned-bad-data-zip": "learned:@/zip_bad_data.zip",
    "learned-missing": "learned:nosuch.zip",
    "learned-no-path": "learned:",
}
"""``evaluate --agents`` values that must be refused."""
EVALUATE_ENVS = {
    "unknown": ("NoSuch-v0", "refuse"),
    "not-ours": ("CartPole-v1", "refuse"),
    "empty": ("", "refuse"),
    "no-plan": ("HouseExplore-v0:", "refuse"),
    "missing-plan": ("HouseExplore-v0:nosuch.json", "refuse"),
    "empty-folder": ("HouseExplore-v0:@/empty_dir", "refuse"),
    "all-plans-bad": ("HouseExplore-v0:@/hostile_set", "refuse"),
    "some-plans-bad": ("HouseExplore-v0:@/mixed", "repair"),
    "glob-matching-nothing": ("HouseExplore-v0:@/nomatch*.json", "refuse"),
    "plan-accept": ("HouseExplore-v0:@/house.json", "accept"),
}
"""``evaluate --envs`` values with their expectations."""
EVALUATE_ENV_KWARGS = {
    "not-json": "not json",
    "not-object": "[1]",
    "unknown": '{"nosuch": 1}',
    "robot-radius-100m": '{"robot": {"radius_m": 100}}',
    "robot-radius-nan": '{"robot": {"radius_m": NaN}}',
    "area-negative": '{"area_m2": -1}',
    "area-1e308": '{"area_m2": 1e308}',
    "lidar-no-beams": '{"lidar": {"n_beams": 0}}',
    "coverage-2": '{"coverage_target": 2}',
    "victims-on-explore": '{"victims": {"n_victims": 1}}',
    "resolution-1e-9": '{"world": {"resolution_m": 1e-9}}',
    "plan-path-binary": '{"plan_path": "@/binary.json"}',
    "building-type-unknown": '{"building_type": "castle"}',
    "render-mode": '{"render_mode": "nosuch"}',
    "wall-thickness-100": '{"world": {"wall_thickness_m": 100}}',
}
"""``evaluate --env-kwargs`` values that must be refused."""
EVALUATE_OVERWRITE_REFUSED = {
    "unknown-agent": _ev("nosuch", more="--overwrite"),
    "max-steps=-1": _ev(more="--overwrite --max-steps -1"),
    "episodes=0": _ev(more="--overwrite --episodes 0"),
    "bad-plan-strict": _ev(envs="HouseExplore-v0:@/binary.json", more="--overwrite --strict"),
    "bad-plan": _ev(envs="HouseExplore-v0:@/binary.json", more="--overwrite"),
    "env-kwargs": _ev(more="--overwrite --env-kwargs '{\"nosuch\": 1}'"),
    "unknown-env": _ev(envs="NoSuch-v0", more="--overwrite"),
    "bad-model": _ev("ppo:@/not_a_zip.zip", more="--overwrite"),
}
"""``evaluate --overwrite`` runs refused for another reason: the earlier run must survive."""


def evaluate_cases() -> list[Case]:
    """``evaluate``: refused options after ``--overwrite``, bad agents, environments and keywords."""
    prior = prior_evaluation("ev")
    out = (
        "evaluate --agents random --envs HouseExplore-v0 --episodes 1 --max-steps 5 --workers 1 --quiet --out"
    )
    symlinked_log = (
        copy("house.json", "precious.jsonl"),
        make_dir("ev"),
        symlink("../precious.jsonl", "ev/episodes.jsonl"),
    )
    cases = [
        _cli("evaluate/accept/house", "accept", _ev(), outputs="ev"),
        _cli("evaluate/prior-run-no-overwrite", "refuse", _ev(), prior),
        _cli("evaluate/resume-and-overwrite", "refuse", _ev(more="--resume --overwrite"), prior),
        _cli("evaluate/out-is-a-file", "refuse", f"{out} @/house.json"),
        _cli("evaluate/out-inside-a-file", "refuse", f"{out} @/house.json/ev"),
        _cli("evaluate/read-only-out", READ_ONLY_EXPECT, f"{out} ro/ev", read_only("ro"), outputs="ro/ev"),
        _cli("evaluate/ray-not-installed", "refuse", _ev(more="--ray")),
        _cli(
            "evaluate/resume-garbage-log",
            "any",
            _ev(more="--resume"),
            prior,
            copy("binary.json", "ev/episodes.jsonl"),
            outputs="ev/*",
        ),
        _cli(
            "evaluate/resume-not-utf8-log",
            "any",
            _ev(more="--resume"),
            prior,
            copy("not_utf8.json", "ev/episodes.jsonl"),
            outputs="ev/*",
        ),
        _cli(
            "evaluate/resume-garbage-results",
            "any",
            _ev(more="--resume"),
            prior,
            copy("binary.json", "ev/results.json"),
            outputs="ev/*",
        ),
        _cli(
            "evaluate/resume-log-is-folder",
            "any",
            _ev(more="--resume"),
            make_dir("ev/episodes.jsonl"),
            write("ev/results.json", "{}"),
            outputs="ev/*",
        ),
        _cli(
            "evaluate/overwrite-through-symlinked-log",
            "accept",
            _ev(more="--overwrite"),
            *symlinked_log,
            outputs="ev/*",
        ),
        _cli(
            "evaluate/subprocess/overwrite-unknown-agent",
            "refuse",
            EVALUATE_OVERWRITE_REFUSED["unknown-agent"],
            prior,
            run_in="cli",
        ),
    ]
    cases += [
        _cli(f"evaluate/overwrite-then-refused/{w}", "refuse", c, prior)
        for w, c in EVALUATE_OVERWRITE_REFUSED.items()
    ]
    cases += [_cli(f"evaluate/agents/{w}", "refuse", _ev(a)) for w, a in EVALUATE_AGENTS.items()]
    cases += [
        _cli(f"evaluate/envs/{w}", expect, _ev(envs=e), outputs="" if expect == "refuse" else "ev")
        for w, (e, expect) in EVALUATE_ENVS.items()
    ]
    cases += [
        _cli("evaluate/corpus-folder", "repair", _ev(envs="HouseExplore-v0:@/"), outputs="ev"),
        _cli(
            "evaluate/env-kwargs/max-steps",
            "refuse",
            "evaluate --agents random --envs HouseExplore-v0 --episodes 1 --workers 1 --out ev "
            "--env-kwargs '{\"max_steps\": -5}'",
        ),
    ]
    kwargs = EVALUATE_ENV_KWARGS.items()
    return cases + [
        _cli(f"evaluate/env-kwargs/{w}", "refuse", _ev(more=f"--env-kwargs {shlex.quote(k)}"))
        for w, k in kwargs
    ]


def train_cases() -> list[Case]:
    """``train`` with arguments that must be refused before training starts."""
    return [
        _cli("train/envs-unknown", "refuse", f"{TRAIN} --envs NoSuch-v0"),
        _cli("train/envs-empty", "refuse", f"{TRAIN} --envs ''"),
        _cli("train/envs-not-ours", "refuse", f"{TRAIN} --envs CartPole-v1"),
        _cli("train/eval-envs-unknown", "refuse", f"{TRAIN} --eval-envs NoSuch-v0"),
        _cli("train/eval-envs-empty", "refuse", f"{TRAIN} --eval-envs ''"),
        _cli("train/out-not-zip", "refuse", f"{TRAIN} --out m.txt"),
        _cli("train/out-exists", "refuse", TRAIN, copy("not_a_zip.zip", "m.zip")),
        _cli("train/out-json-exists", "refuse", TRAIN, copy("house.json", "m.json")),
        _cli(
            "train/overwrite-then-refused",
            "refuse",
            f"{TRAIN} --overwrite --timesteps -1",
            copy("not_a_zip.zip", "m.zip"),
            copy("house.json", "m.json"),
        ),
        _cli("train/out-inside-a-file", "refuse", f"{TRAIN} --out @/house.json/m.zip"),
        _cli("train/out-is-folder", "refuse", TRAIN, make_dir("m.zip")),
        _cli(
            "train/eval-out-inside-a-file", "refuse", f"{TRAIN} --eval-episodes 1 --eval-out @/house.json/e"
        ),
        _cli("train/no-train-missing-model", "refuse", NO_TRAIN),
        _cli("train/no-train-not-a-zip", "refuse", NO_TRAIN, copy("not_a_zip.zip", "m.zip")),
        _cli("train/no-train-zip-without-model", "refuse", NO_TRAIN, copy("zip_without_model.zip", "m.zip")),
        _cli("train/no-train-bad-data-zip", "refuse", NO_TRAIN, copy("zip_bad_data.zip", "m.zip")),
        _cli("train/no-train-empty-zip", "refuse", NO_TRAIN, copy("empty.zip", "m.zip")),
        _cli(
            "train/learned-with-vec-env", "refuse", "train --preset learned-smoke --vec-env dummy --out m.zip"
        ),
        _cli("train/unknown-preset", "refuse", "train --preset nosuch --out m.zip"),
        _cli("train/subprocess/timesteps=-1", "refuse", f"{TRAIN} --timesteps -1", run_in="cli"),
    ]


_ENV = "realistic_indoor.envs"
_SIM = "realistic_indoor.sim"


def api_cases() -> list[Case]:
    """The Python API: load/save, gymnasium environments and config classes with absurd values."""
    p = functools.partial
    cases = [
        _api("load/accept", "accept", p(api_load, name="@/house.json")),
        _api("load/unknown-format-name", "refuse", p(api_load, name="@/house.json", fmt="nosuch")),
        _api("load/writable-only-format", "refuse", p(api_load, name="@/house.json", fmt="png")),
        _api("load/unknown-option", "refuse", p(api_load, name="@/house.json", nosuch=1)),
        _api("load/huge-file", "refuse", p(api_load, name="big.json"), sparse_file("big.json", 300)),
        _api("load/fifo", "refuse", p(api_load, name="pipe.json"), fifo("pipe.json"), timeout_s=20),
        _api("save/accept", "accept", p(api_save, target="out.json"), outputs="out.json"),
        _api("save/unknown-ending", "refuse", p(api_save, target="out.foo")),
        _api("save/inside-a-file", "refuse", p(api_save, target="@/house.json/out.json")),
        _api("save/folder", "refuse", p(api_save, target="out.json"), make_dir("out.json")),
        _api("save/writable-only-format", "accept", p(api_save, target="out.png"), outputs="out.png"),
        _api("env/accept-plan-path", "accept", p(api_episode, plan_path="@/house.json")),
        _api("env/accept-building", "accept", p(api_episode, building="@load:house.json")),
        _api("env/accept-source-xml", "accept", p(api_episode, source="@/house.xml")),
        _api("env/building-is-a-path", "refuse", p(api_episode, building="@/house.json")),
        _api("env/building-is-a-number", "refuse", p(api_episode, building=42)),
        _api("env/plan-path-is-a-number", "refuse", p(api_episode, plan_path=42)),
        _api(
            "env/building-and-plan-path",
            "refuse",
            p(api_episode, building="@load:house.json", plan_path="@/house.json"),
        ),
        _api("env/source-unknown-name", "refuse", p(api_episode, source="castle")),
        _api("env/unknown-keyword", "refuse", p(api_episode, nosuch=1)),
        _api("env/render-mode-unknown", "refuse", p(api_episode, render_mode="nosuch")),
        _api("env/victims-on-explore", "refuse", p(api_episode, victims={"n_victims": 1})),
        _api(
            "env/search-1000-victims-in-a-house",
            "any",
            p(api_episode, env_id="HouseSearch-v0", plan_path="@/house.json", victims={"n_victims": 1000}),
        ),
        _api("env/step-before-reset", "refuse", p(api_episode, reset=False)),
        _api("env/step-nan-action", "refuse", p(api_episode, action=[math.nan, 0.0])),
        _api("env/step-text-action", "refuse", p(api_episode, action="abc")),
        _api("env/step-wrong-shape", "refuse", p(api_episode, action=[0.0, 0.0, 0.0])),
        _api("env/step-huge-action", "any", p(api_episode, action=[1e308, -1e308])),
        _api("env/reset-building-text", "refuse", p(api_episode, options={"building": "x"})),
        _api("env/reset-unknown-option", "refuse", p(api_episode, options={"nosuch": 1})),
        _api("env/reset-seed-negative", "refuse", p(api_episode, seed=-1)),
        _api("env/reset-seed-text", "refuse", p(api_episode, seed="abc")),
        _api("vector/accept", "accept", p(api_vector, plan_path="@/house.json")),
        _api("vector/num-envs-0", "refuse", p(api_vector, num_envs=0)),
        _api("vector/num-envs-negative", "refuse", p(api_vector, num_envs=-1)),
        _api("vector/num-envs-fraction", "refuse", p(api_vector, num_envs=2.5)),
        _api("vector/num-envs-text", "refuse", p(api_vector, num_envs="abc")),
        _api(
            "vector/robot-radius-100m",
            "refuse",
            p(api_vector, plan_path="@/house.json", robot={"radius_m": 100}),
        ),
        _api(
            "vector/sync-binary-plan",
            "refuse",
            p(api_vector, plan_path="@/binary.json", vectorization_mode="sync"),
        ),
    ]
    cases += [
        _api(f"vector/plan/{name}", "refuse", p(api_vector, plan_path=f"@/{name}"))
        for name in ("binary.json", "no_rooms.json", "nan_coords.json", "grid_100000.wg.xml", "scale_nan.xml")
    ]
    env_values: dict[str, list[Any]] = {
        "robot.radius_m": [100, math.nan, -1, 0, math.inf],
        "robot.max_speed_m_s": [-1, math.nan, 1e308],
        "robot.control_hz": [0, -1, math.nan],
        "robot.substeps": [0, -1, 2.5],
        "lidar.n_beams": [0, -1, 2.5],
        "lidar.max_range_m": [math.nan, -1, math.inf],
        "lidar.noise_std_m": [-1, math.nan],
        "lidar.fov_rad": [0, -1, math.nan],
        "world.resolution_m": [0, -1, math.nan, 1e-9, 1e308],
        "world.wall_thickness_m": [100, -1, math.nan],
        "local_map.size_px": [0, -1, 10**6],
        "local_map.resolution_m": [0, math.nan],
        "rewards.new_area": [math.nan, math.inf],
        "macro.n_candidates": [0, -1],
        "max_steps": [0, -1, math.nan, 1.5, True],
        "coverage_target": [0, 2, math.nan, -1],
        "area_m2": [-1, math.nan, 1e308, 0, "abc"],
        "building_type": ["castle"],
        "action_type": ["nosuch"],
        "extra_observations": ["global_map", ("nosuch",)],
    }
    for key, values in env_values.items():
        group, _, field_name = key.rpartition(".")
        for value in values:
            kwargs = {group: {field_name: value}} if group else {field_name: value}
            cases.append(_api(f"env/{key}={value!r}", "refuse", p(api_episode, **kwargs)))
    configs = {
        f"{_SIM}.robot:RobotConfig": {"radius_m": [-1, math.nan]},
        f"{_SIM}.lidar:LidarConfig": {"n_beams": [0], "fov_rad": [math.nan]},
        f"{_SIM}.world:WorldConfig": {"resolution_m": [0, math.inf]},
        f"{_SIM}.mapping:LocalMapConfig": {"size_px": [-1]},
        f"{_SIM}.victims:VictimConfig": {"n_victims": [-1], "sensor_range_m": [math.nan]},
        f"{_ENV}.rewards:RewardWeights": {"new_area": [math.inf]},
        f"{_ENV}.macro:MacroConfig": {"n_candidates": [0], "waypoint_grid": [-1]},
        f"{_ENV}.observations:GlobalMapConfig": {"size_px": [0]},
        f"{_ENV}.config:EnvConfig": {"max_steps": [0, True], "coverage_target": [math.nan], "source": [42]},
        "realistic_indoor.agents.rl.config:PPOConfig": {
            "total_timesteps": [-1],
            "learning_rate": [math.nan],
            "env_ids": [("NoSuch-v0",)],
            "n_envs": [0],
        },
        "realistic_indoor.agents.rl.learned:LearnedConfig": {"n_envs": [0], "gamma": [math.nan]},
        "realistic_indoor.agents.structure:StructureConfig": {"room_factor": [math.nan, -1]},
        "realistic_indoor.agents.utility:UtilityConfig": {"cost_weight": [math.nan], "gain_radius_m": [-1]},
    }
    for target, fields in configs.items():
        for field_name, values in fields.items():
            for value in values:
                what = f"config/{target.rpartition(':')[2]}.{field_name}={value!r}"
                cases.append(_api(what, "refuse", p(api_construct, target=target, **{field_name: value})))
    make = "realistic_indoor.generator:make_generator"
    generators: dict[str, tuple[tuple[Any, ...], dict[str, Any]]] = {
        "area=-1": (("office", -1), {}),
        "area=nan": (("office", math.nan), {}),
        "area=inf": (("office", math.inf), {}),
        "area=1e308": (("office", 1e308), {}),
        "area=text": (("office", "abc"), {}),
        "unknown-name": (("castle",), {}),
        "unknown-option": (("office",), {"nosuch": 1}),
        "grid-0": (("random",), {"width_units": 0, "height_units": 5}),
        "grid-100000": (("random",), {"width_units": 100000, "height_units": 100000}),
        "model-text": (("office",), {"model": "nosuch"}),
    }
    cases += [
        _api(f"generator/{what}", "refuse", p(api_construct, target=make, args=args, **kwargs))
        for what, (args, kwargs) in generators.items()
    ]
    return cases


def all_cases() -> list[Case]:
    """Every case of the sweep, in the order they run."""
    cases = [
        *plan_cases(),
        *info_cases(),
        *validate_cases(),
        *render_cases(),
        *convert_cases(),
        *generate_cases(),
        *evaluate_cases(),
        *train_cases(),
        *numeric_cases(),
        *api_cases(),
    ]
    names = Counter(c.name for c in cases)
    duplicates = [n for n, k in names.items() if k > 1]
    if duplicates:
        raise ValueError(f"duplicate case names: {duplicates[:5]}")
    return cases


# -- reporting ----------------------------------------------------------------------------------------------


def report(results: list[dict[str, Any]]) -> str:
    """A table per category, the failing cases grouped by problem, and the summary line."""
    shown = ("ok", *PROBLEMS)
    header = f"{'category':10s} {'cases':>5s} " + " ".join(f"{h[:10]:>10s}" for h in shown)
    lines = [header, "-" * len(header)]
    for category in dict.fromkeys(r["category"] for r in results):
        rows = [r for r in results if r["category"] == category]
        counts = Counter(p for r in rows for p in r["problems"])
        counts["ok"] = sum(1 for r in rows if not r["problems"])
        lines.append(f"{category:10s} {len(rows):5d} " + " ".join(f"{counts[h]:10d}" for h in shown))
    failing = [r for r in results if r["problems"]]
    if failing:
        lines += ["", "failing cases (first problem, expected, what happened):"]
        for problem in PROBLEMS:
            for r in (r for r in failing if r["problems"][0] == problem):
                lines.append(f"  {problem:14s} {r['name']}  [expect {r['expect']}]  {r['message'][:200]}")
    lines += ["", summary_line(results)]
    return "\n".join(lines)


# -- the command line ----------------------------------------------------------------------------------------


def _set_memory_limit(gigabytes: float) -> None:
    if gigabytes > 0:
        _limit_memory(gigabytes)()


def _run_one_in_child(name: str, root: Path) -> int:
    """``--run-case``: run one case here (the parent watches the files) and print its outcome as JSON."""
    case = next(c for c in all_cases() if c.name == name)
    ctx = Ctx(root / "in", case_folder(root, case))
    outcome = execute(case, ctx)
    print(json.dumps(dataclasses.asdict(outcome)))
    return 0


def sweep(cases: list[Case], keep: bool = False, progress: bool = True) -> tuple[list[dict[str, Any]], Path]:
    """Run ``cases`` in a fresh temporary folder; their results and the folder."""
    root = Path(tempfile.mkdtemp(prefix="hostile_sweep_"))
    build_inputs(root)
    results = []
    start = time.perf_counter()
    for i, case in enumerate(cases, 1):
        result = run_case(case, root, keep)
        results.append(result)
        if progress and result["problems"]:
            print(
                f"[{i}/{len(cases)}] {','.join(result['problems'])}: {case.name}: {result['message'][:160]}",
                file=sys.stderr,
                flush=True,
            )
        elif progress and i % 50 == 0:
            print(f"[{i}/{len(cases)}] {time.perf_counter() - start:.0f} s", file=sys.stderr, flush=True)
    if not keep:
        _remove(root)
    return results, root


def main(argv: list[str] | None = None) -> int:
    """Run the sweep; 0 only when every case is ok."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", help="run only the cases whose name contains this")
    parser.add_argument("--json", help="write every case's result to this file")
    parser.add_argument("--list", action="store_true", help="list the cases and exit")
    parser.add_argument("--keep", action="store_true", help="keep the temporary folder (printed)")
    parser.add_argument("--memory-gb", type=float, default=8.0, help="address-space limit of this process")
    parser.add_argument("--write-corpus", action="store_true", help="rebuild tests/data/hostile/ and exit")
    parser.add_argument("--run-case", help=argparse.SUPPRESS)
    parser.add_argument("--root", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    os.environ.setdefault("MPLBACKEND", "Agg")
    if args.write_corpus:
        print(f"wrote {len(write_corpus())} files to {CORPUS}")
        return 0
    if args.run_case:
        _set_memory_limit(CHILD_MEMORY_GB)
        return _run_one_in_child(args.run_case, Path(args.root))
    cases = [c for c in all_cases() if not args.only or args.only in c.name]
    if not cases:
        print(f"no case name contains {args.only!r} (--list lists them)", file=sys.stderr)
        return 2
    if args.list:
        print("\n".join(f"{c.name}  [{c.expect}]" for c in cases))
        return 0
    _set_memory_limit(args.memory_gb)
    start = time.perf_counter()
    results, root = sweep(cases, keep=args.keep)
    print(report(results))
    print(f"({time.perf_counter() - start:.0f} s{f'; cases kept in {root}' if args.keep else ''})")
    if args.json:
        Path(args.json).write_text(json.dumps(results, indent=1, default=str) + "\n", encoding="utf-8")
    return 0 if all(not r["problems"] for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
