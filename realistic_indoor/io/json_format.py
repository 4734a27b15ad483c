"""Lossless JSON: every field of a ``Building``, under a versioned schema."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from realistic_indoor.building import Building, Door, Room
from realistic_indoor.errors import PlanFormatError
from realistic_indoor.files import write_text

__all__ = ["SCHEMA", "SCHEMA_VERSION", "dumps", "from_dict", "loads", "read", "to_dict", "write"]

SCHEMA = "realistic-indoor/building"
SCHEMA_VERSION = 1


def to_dict(b: Building) -> dict[str, Any]:
    """The building as plain JSON-ready data (floats kept exactly)."""
    return {
        "schema": SCHEMA,
        "version": SCHEMA_VERSION,
        "building_type": b.building_type.value,
        "metadata": b.metadata,
        "rooms": [
            {
                "id": r.id,
                "label": r.label.value,
                "function": r.function,
                "outline": [list(p) for p in r.outline],
            }
            for r in b.rooms
        ],
        "doors": [
            {
                "id": d.id,
                "rooms": [d.room_a, d.room_b],
                "x": d.x,
                "y": d.y,
                "width_m": d.width_m,
                "angle_rad": d.angle_rad,
            }
            for d in b.doors
        ],
    }


def from_dict(data: dict[str, Any], source: str = "<data>") -> Building:
    """Rebuild a building from :func:`to_dict` output.

    Raises:
        PlanFormatError: If the schema or version is not this one, or a field is missing.
    """
    if not isinstance(data, dict) or data.get("schema") != SCHEMA:
        raise PlanFormatError(source, f'not a building file (expected "schema": "{SCHEMA}")')
    if data.get("version") != SCHEMA_VERSION:
        raise PlanFormatError(
            source,
            f"schema version {data.get('version')!r} is not supported (this version reads {SCHEMA_VERSION})",
        )
    element = "building"
    try:
        rooms = []
        for i, r in enumerate(data["rooms"]):
            element = f"rooms[{i}]"
            rooms.append(Room(r["id"], r["label"], r["function"], tuple(tuple(p) for p in r["outline"])))
        doors = []
        for i, d in enumerate(data["doors"]):
            element = f"doors[{i}]"
            a, b = d["rooms"]
            doors.append(Door(d["id"], a, b, d["x"], d["y"], d["width_m"], d["angle_rad"]))
        element = "building"
        return Building(data["building_type"], tuple(rooms), tuple(doors), dict(data.get("metadata", {})))
    except KeyError as e:
        raise PlanFormatError(source, f"missing field {e}", element) from None
    except (TypeError, ValueError, OverflowError) as e:
        raise PlanFormatError(source, f"invalid value: {e}", element) from None


def dumps(b: Building) -> str:
    """The building as a JSON string (stable key order, so equal buildings give equal text)."""
    return json.dumps(to_dict(b), indent=1, sort_keys=True)


def loads(text: str, source: str = "<string>") -> Building:
    """Parse a building from :func:`dumps` output."""
    try:
        data = json.loads(text)
    except json.JSONDecodeError as e:
        raise PlanFormatError(source, f"malformed JSON: {e}") from None
    except RecursionError:
        raise PlanFormatError(source, "malformed JSON: nested too deeply to be a building file") from None
    except ValueError as e:  # e.g. an integer of more digits than Python converts
        raise PlanFormatError(source, f"malformed JSON: {e}") from None
    return from_dict(data, source)


def read(path: str | Path) -> Building:
    """Read a building from a JSON file (UTF-8).

    Raises:
        PlanFormatError: If the file cannot be read, is not UTF-8 text, or is not a building file.
    """
    try:
        data = Path(path).read_bytes()
    except OSError as e:
        raise PlanFormatError(path, f"cannot read the file ({e.strerror or e})") from None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise PlanFormatError(path, f"not UTF-8 text (byte {e.start}): is it a JSON plan?") from None
    return loads(text, str(path))


def write(b: Building, path: str | Path) -> list[Path]:
    """Write a building to a JSON file."""
    return [write_text(path, dumps(b) + "\n")]
