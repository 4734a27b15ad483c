"""The repository itself: what a fresh clone gets must work on any machine."""

from __future__ import annotations

import ast
import re
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

# Absolute paths that only exist on the machine where a file was written.
MACHINE_PATH = re.compile(rb"(?<![\w.])(/work/|/home/\w|/root/|/Users/\w|[A-Z]:\\\\Users)")


def _tracked() -> list[tuple[str, str]]:
    """``(mode, path)`` of every tracked file."""
    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("not a git checkout (installed from a source distribution)")
    out = subprocess.run(
        ["git", "ls-files", "-s", "-z"], cwd=ROOT, capture_output=True, check=True
    ).stdout.decode()
    rows = [entry.split("\t", 1) for entry in out.split("\0") if entry]
    return [(meta.split()[0], path) for meta, path in rows]


def test_repository__tracks_no_symbolic_link():
    links = [path for mode, path in _tracked() if mode == "120000"]
    assert links == [], f"symbolic links break a fresh clone: {links}"


def test_repository__tracks_no_virtual_environment():
    venvs = [p for _, p in _tracked() if p.split("/")[0] in (".venv", "venv") or "/site-packages/" in p]
    assert venvs == []


def test_repository__text_files_name_no_machine_path():
    found = []
    for _, path in _tracked():
        if path.endswith((".zip", ".png", ".pgm")) or path == "tests/test_repository.py":
            continue
        data = (ROOT / path).read_bytes()
        found += [f"{path}: {m.group(0).decode()}" for m in MACHINE_PATH.finditer(data)]
    assert found == [], f"machine-specific paths: {found[:5]}"


def test_repository__gitignore_ignores_venv_folder_and_link(tmp_path):
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    for name in (".venv", ".venv/pyvenv.cfg", "runs/x.json"):
        out = subprocess.run(["git", "check-ignore", "--no-index", "-q", name], cwd=ROOT, capture_output=True)
        assert out.returncode == 0, f"{name} is not ignored"


def test_version__matches_pyproject():
    from realistic_indoor.version import __version__

    declared = re.search(r'^version = "([^"]+)"', (ROOT / "pyproject.toml").read_text(), re.MULTILINE)
    assert declared is not None and __version__ == declared.group(1)


def _skips_own_import_failure(tree: ast.AST) -> list[int]:
    """Lines where a test skips because an import of the project's own code failed."""
    lines = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and getattr(node.func, "attr", "") == "importorskip":
            first = node.args[0] if node.args else None
            if isinstance(first, ast.Constant) and str(first.value).startswith("realistic_indoor"):
                lines.append(node.lineno)
        if isinstance(node, ast.Try):
            imports_own = any(
                isinstance(n, (ast.Import, ast.ImportFrom))
                and any(
                    (getattr(n, "module", None) or a.name).startswith("realistic_indoor") for a in n.names
                )
                for stmt in node.body
                for n in ast.walk(stmt)
            )
            skips = any(
                isinstance(n, ast.Call) and getattr(n.func, "attr", "") == "skip"
                for h in node.handlers
                for stmt in h.body
                for n in ast.walk(stmt)
            )
            if imports_own and skips:
                lines.append(node.lineno)
    return lines


def test_tests__never_skip_when_the_projects_own_code_fails_to_import():
    """A broken module of the package must show as an error, not as skipped tests."""
    found = [
        f"{path.relative_to(ROOT)}:{line}"
        for path in sorted((ROOT / "tests").rglob("*.py"))
        for line in _skips_own_import_failure(ast.parse(path.read_text()))
    ]
    assert found == []


def test_skip_check__finds_both_forms():
    source = (
        "import pytest\n"
        "gen = pytest.importorskip('realistic_indoor.generator')\n"
        "try:\n"
        "    from realistic_indoor.sim import World\n"
        "except ImportError:\n"
        "    pytest.skip('no sim')\n"
        "mj = pytest.importorskip('mujoco')\n"
    )
    assert sorted(_skips_own_import_failure(ast.parse(source))) == [2, 3]
