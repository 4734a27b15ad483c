"""Functional room labels (office, classroom, toilet, ...) and the semantic label each one maps to.

The default table is package data (``realistic_indoor/data/function_labels.json``); a user's
dict or JSON file updates it, so a plan with labels of its own can still be read.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from functools import lru_cache
from importlib import resources
from pathlib import Path
from typing import Any

from realistic_indoor.building.labels import SemanticLabel, normalise_function, parse_label
from realistic_indoor.errors import ConfigError

__all__ = ["LabelMap", "default_label_map", "load_label_map", "semantic_label_for"]

LabelMap = dict[str, SemanticLabel]
"""Functional label (normalised, see :func:`~realistic_indoor.building.labels.normalise_function`)
-> semantic label."""


@lru_cache(maxsize=1)
def _default_table() -> dict[str, str]:
    text = resources.files("realistic_indoor").joinpath("data/function_labels.json").read_text("utf-8")
    return json.loads(text)["labels"]


def default_label_map() -> LabelMap:
    """The package's table, as a new dict the caller may change."""
    return {k: SemanticLabel(v) for k, v in _default_table().items()}


def load_label_map(override: Mapping[str, Any] | str | Path | None = None) -> LabelMap:
    """The default table updated by ``override``.

    Args:
        override: ``None`` (the default table), a mapping ``{functional label: semantic label}``
            (values like ``"medium"``, ``"M"`` or a :class:`SemanticLabel`), or the path of a JSON
            file holding such an object, either flat or under a ``"labels"`` key as in the
            package's own table.

    Returns:
        A new dict from normalised functional labels to semantic labels.

    Raises:
        ConfigError: If the file cannot be read or parsed, or a value names no semantic label.

    Examples:
        >>> load_label_map({"Server Room": "M"})["server room"]
        <SemanticLabel.MEDIUM: 'medium'>
    """
    table = default_label_map()
    if override is None:
        return table
    if isinstance(override, (str, Path)):
        override = _read_json_table(Path(override))
    if not isinstance(override, Mapping):
        raise ConfigError(f"label map must be a mapping or a JSON file path, not {type(override).__name__}")
    for key, value in override.items():
        if str(key).startswith("_"):
            continue
        try:
            table[normalise_function(key)] = parse_label(value)
        except ConfigError as e:
            raise ConfigError(f"label map entry {key!r}: {e}") from None
    return table


def _read_json_table(path: Path) -> Mapping[str, Any]:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except OSError as e:
        raise ConfigError(f"{path}: cannot read the label map ({e.strerror or e})") from None
    except json.JSONDecodeError as e:
        raise ConfigError(f"{path}: the label map is not valid JSON ({e})") from None
    if isinstance(data, dict) and isinstance(data.get("labels"), dict):
        return data["labels"]
    if not isinstance(data, dict):
        raise ConfigError(f'{path}: the label map must be a JSON object {{"label": "medium", ...}}')
    return data


def semantic_label_for(function: str, label_map: Mapping[str, SemanticLabel] | None = None) -> SemanticLabel:
    """The semantic label of a functional label.

    Args:
        function: A functional label, in any case (``"SHARED OFFICE"``, ``"shared office"``).
        label_map: The table to use (default: :func:`default_label_map`).

    Raises:
        ConfigError: If the table has no entry; the message says how to add one.
    """
    key = normalise_function(function)
    table = default_label_map() if label_map is None else label_map
    try:
        return table[key]
    except KeyError:
        raise ConfigError(
            f"unknown functional label {key!r}; add it to the label map, e.g. "
            f'label_map={{"{key}": "medium"}} or a JSON file {{"{key}": "medium"}} '
            "(semantic labels: corridor, hall, small, medium, big)"
        ) from None
