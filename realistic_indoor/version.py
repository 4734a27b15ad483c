"""The package's version, in the lowest layer so that any module may name it in the files it writes."""

__all__ = ["__version__"]

__version__ = "0.1.0"
"""The release (as ``pyproject.toml``'s ``version``; ``tests/test_repository.py`` checks they agree)."""
