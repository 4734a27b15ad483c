"""The ``realistic-indoor`` command.

Each subcommand is a module of this package with ``register(subparsers)`` (adds its parser and
sets ``func``); modules are found automatically, so a new subcommand is a new file.
Heavy libraries are imported inside the subcommands, so ``--help`` stays fast.
"""

from __future__ import annotations

import argparse
import importlib
import os
import pkgutil
import shlex
import sys
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

from realistic_indoor import __version__
from realistic_indoor.errors import ConfigError, RealisticIndoorError

__all__ = [
    "DEBUG_VARIABLE",
    "INTERNAL_ERROR",
    "build_parser",
    "checkout_commit",
    "main",
    "run_folder",
    "run_script",
    "script_command",
]

INTERNAL_ERROR = 70
"""Exit code of an unexpected exception: a bug, told apart from a refused input (1, 2)."""

DEBUG_VARIABLE = "REALISTIC_INDOOR_DEBUG"
"""Environment variable that, set to 1, lets internal errors show their traceback (as ``--debug``)."""


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with every subcommand registered."""
    parser = argparse.ArgumentParser(
        prog="realistic-indoor",
        description="Structurally realistic buildings for exploration and search-and-rescue robots.",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    parser.add_argument(
        "--debug",
        action="store_true",
        help=f"show the traceback of an internal error (a bug) instead of one line; also {DEBUG_VARIABLE}=1",
    )
    sub = parser.add_subparsers(title="commands", dest="command", metavar="COMMAND")
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda m: m.name):
        if not info.name.startswith("_"):
            module = importlib.import_module(f"{__name__}.{info.name}")
            module.register(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run the command line; returns the exit code.

    Returns:
        0 on success, 1 for a user error (a bad file or value, one line), 2 for a usage error
        (argparse), :data:`INTERNAL_ERROR` for a bug (one line; ``--debug`` shows the traceback),
        130 when interrupted.
    """
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    return run_script(lambda: args.func(args), f"realistic-indoor {args.command}", debug=args.debug)


def checkout_commit(folder: str | os.PathLike[str]) -> str | None:
    """The commit checked out in ``folder``, for scripts to record with their results.

    Returns:
        The full hash of ``HEAD``; ``None`` outside a git checkout or without git.
    """
    import subprocess

    try:
        done = subprocess.run(
            ["git", "rev-parse", "HEAD"], cwd=folder, capture_output=True, text=True, check=True
        )
    except (OSError, subprocess.CalledProcessError):
        return None
    return done.stdout.strip()


def run_folder(out: str | None, default: Path, *, small: bool, report_only: bool, name: str) -> Path:
    """The folder a script of ``experiments/`` writes its run to, or reads it from.

    ``--out`` when given. Otherwise a full run uses ``default``, and a ``--small`` (smoke) run a
    new temporary folder, named after the script, so that it never overwrites a full run's results
    (nor leaves smoke-trained models beside them).

    Args:
        out: The script's ``--out``, ``None`` if not given.
        default: The full run's folder.
        small: Whether this is a ``--small`` run.
        report_only: Whether the run is only read again (``--report-only``).
        name: The script's name, for the temporary folder's.

    Raises:
        ConfigError: For ``--report-only --small`` without ``--out``: there is no small run to read.
    """
    if out:
        return Path(out)
    if not small:
        return default
    if report_only:
        raise ConfigError("--report-only --small needs --out: the folder the small run wrote to")
    import tempfile

    folder = Path(tempfile.mkdtemp(prefix=f"{name}_small_"))
    print(f"--small without --out: writing to {folder}", flush=True)
    return folder


def write_report(
    out: Path,
    name: str,
    analyse: Callable[[list, dict[str, Any]], str],
    results: list | None = None,
    meta: dict[str, Any] | None = None,
) -> int:
    """Write a script's report, ``analyse(results, meta)``, to ``out/NAME.md`` and print it.

    Without ``results`` (``--report-only``) they are read back from ``out/NAME/results.json``,
    where the run wrote them (:func:`~realistic_indoor.evaluation.write_results`).

    Returns:
        0, the script's exit code.
    """
    from realistic_indoor.files import write_text

    if results is None:
        from realistic_indoor.evaluation import read_results

        results, meta = read_results(out / name / "results.json")
    report = analyse(results, meta)
    write_text(out / f"{name}.md", report)
    print(report)
    return 0


def script_command(script: str, argv: list[str] | None) -> str:
    """The command line that ran ``script`` (a path from the project's root), as reports show it.

    Args:
        script: E.g. ``experiments/step_definition.py``.
        argv: The arguments given to the script's ``main``; ``None`` for the process's own.
    """
    given = sys.argv[1:] if argv is None else argv
    return " ".join([f".venv/bin/python {script}", *map(shlex.quote, given)])


def run_script(main_fn: Callable[[], int | None], name: str, debug: bool = False) -> int:
    """Run a script's ``main`` as the command line runs a subcommand: every error on one line.

    For :func:`main` and the scripts of ``experiments/``: a bad argument or file (any
    :class:`~realistic_indoor.errors.RealisticIndoorError`) prints ``NAME: error: ...`` and
    returns 1; a file that cannot be read or written (``OSError``: no permission, a full disk)
    prints ``NAME: error: cannot ...`` and returns 1; anything else is a bug and prints
    ``NAME: internal error: ...`` and returns :data:`INTERNAL_ERROR`, with the traceback only
    under ``debug`` (or the environment variable :data:`DEBUG_VARIABLE` set to 1).

    Args:
        main_fn: The script's entry point, returning its exit code.
        name: The script's name, shown before the message.
        debug: Let an internal error raise, with its traceback.

    Returns:
        The exit code: ``main_fn``'s (0 when it returns ``None``), 1 on a user error, 70 on a
        bug, 130 when interrupted, 0 when the reader of the output went away (``| head``).
    """
    shown = _Warnings()
    debug = debug or os.environ.get(DEBUG_VARIABLE) == "1"
    with warnings.catch_warnings():
        warnings.simplefilter("always", UserWarning)  # every repair and lossy export, each time
        warnings.showwarning = shown.show
        return _run(main_fn, name, shown, debug)


def _run(main_fn: Callable[[], int | None], name: str, shown: _Warnings, debug: bool) -> int:
    try:
        return int(main_fn() or 0)
    except RealisticIndoorError as e:
        print(f"{name}: error: {_one_line(str(e))}", file=sys.stderr)
        return 1
    except BrokenPipeError:
        # The reader of our output went away (e.g. `| head`): not an error of ours.
        sys.stderr = open(os.devnull, "w")  # noqa: SIM115 - silence the interpreter's flush at exit
        return 0
    except OSError as e:
        if debug:
            raise
        print(f"{name}: error: {_os_error(e)}", file=sys.stderr)
        return 1
    except MemoryError:
        if debug:
            raise
        print(f"{name}: error: out of memory; try a smaller plan, resolution or batch", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except Exception as e:
        if debug:
            raise
        print(
            f"{name}: internal error: {type(e).__name__}: {_one_line(str(e))} (a bug: please report it "
            f"with the traceback that --debug or {DEBUG_VARIABLE}=1 shows)",
            file=sys.stderr,
        )
        return INTERNAL_ERROR
    finally:
        shown.summarise()


def _one_line(text: str) -> str:
    """``text`` with its line breaks replaced, so that an error stays one line."""
    return " ".join(text.split("\n")).strip() if "\n" in text else text


def _os_error(e: OSError) -> str:
    """An ``OSError`` as the user needs it: what could not be done to which file, and why."""
    import errno

    where = f" {e.filename}" if e.filename else ""
    hint = {
        errno.ENOSPC: "; free some space or write elsewhere",
        errno.EACCES: "; check the permissions or write elsewhere",
        errno.EROFS: "; write elsewhere",
    }.get(e.errno or 0, "")
    return f"cannot use{where}: {e.strerror or e}{hint}"


class _Warnings:
    """Prints warnings as one line each, without the source line.

    Plan repairs are printed for the first plan that needs any; those of further plans are
    counted in one line at the end, so that a folder of messy plans does not bury the
    command's own output.
    """

    def __init__(self) -> None:
        self.repairs: list[str] = []

    def show(self, message, category, filename, lineno, file=None, line=None) -> None:
        from realistic_indoor.io.floorplan.repairs import PlanRepairWarning

        if issubclass(category, PlanRepairWarning):
            self.repairs.append(str(message))
            if _plan_of(self.repairs[-1]) != _plan_of(self.repairs[0]):
                return
        print(f"realistic-indoor: warning: {message}", file=file or sys.stderr)

    def summarise(self) -> None:
        first = _plan_of(self.repairs[0]) if self.repairs else None
        hidden = [m for m in self.repairs if _plan_of(m) != first]
        if hidden:
            plans = len({_plan_of(m) for m in hidden})
            print(
                f"realistic-indoor: warning: {len(hidden)} repairs in {plans} more plans not shown; "
                "'realistic-indoor info PLAN' lists a plan's repairs, --strict refuses such plans",
                file=sys.stderr,
            )


def _plan_of(repair_message: str) -> str:
    """The file a plan-repair message names (its text before the first ``": "``)."""
    return repair_message.split(": ", 1)[0]


if __name__ == "__main__":
    sys.exit(main())
