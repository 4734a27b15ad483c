import ast
from pathlib import Path

import realistic_indoor.agents

AGENTS_DIR = Path(realistic_indoor.agents.__file__).parent


def _imports(path: Path) -> list[tuple[str, str]]:
    """``(module, name)`` of each ``from realistic_indoor... import name`` outside the agents package."""
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("realistic_indoor."):
            if not node.module.startswith("realistic_indoor.agents"):
                out += [(node.module, alias.name) for alias in node.names]
        elif isinstance(node, ast.Import):
            out += [(alias.name, "") for alias in node.names if alias.name.startswith("realistic_indoor.")]
    return out


def test_agents__import_only_public_names_of_the_other_packages():
    private = [
        f"{path.relative_to(AGENTS_DIR)}: {module} {name}".rstrip()
        for path in sorted(AGENTS_DIR.rglob("*.py"))
        for module, name in _imports(path)
        if any(part.startswith("_") for part in module.split(".")) or name.startswith("_")
    ]
    assert not private
