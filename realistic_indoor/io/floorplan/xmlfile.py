"""Parsing helpers of the floor-plan reader, with errors that name the file and the element."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

from realistic_indoor.errors import PlanFormatError

__all__ = ["UNIT_M", "number", "parse_root", "point", "points", "read_scale"]

UNIT_M: dict[str, float] = {
    "mm": 0.001,
    "cm": 0.01,
    "dm": 0.1,
    "m": 1.0,
    "km": 1000.0,
    "in": 0.0254,
    "inch": 0.0254,
    "inches": 0.0254,
    "ft": 0.3048,
    "foot": 0.3048,
    "feet": 0.3048,
    "yd": 0.9144,
}
"""Length units a ``<real_distance>`` may use, in metres."""

PIXEL_UNITS = ("pixel", "pixels", "px")

_SCALE_HELP = (
    "add <scale><represented_distance><value>PIXELS</value><um>pixel</um></represented_distance>"
    "<real_distance><value>LENGTH</value><um>cm</um></real_distance></scale>"
)


def parse_root(path: Path) -> ET.Element:
    """Parse ``path`` and return its root element.

    Raises:
        PlanFormatError: If the file is missing or unreadable, or the XML is malformed (the message
            gives line and column).
    """
    try:
        tree = ET.parse(path)
    except FileNotFoundError:
        raise PlanFormatError(path, "no such file") from None
    except IsADirectoryError:
        raise PlanFormatError(path, "is a directory, not a plan file") from None
    except OSError as e:
        raise PlanFormatError(path, f"cannot read the file ({e.strerror or e})") from None
    except ET.ParseError as e:
        line, column = e.position
        reason = str(e).split(": line")[0]
        raise PlanFormatError(path, f"malformed XML at line {line}, column {column + 1}: {reason}") from None
    return tree.getroot()


def number(text: str | None, path: Path, element: str, what: str) -> float:
    """``text`` as a finite float, or a :class:`PlanFormatError` naming ``element`` and ``what``."""
    try:
        value = float(text)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        value = math.nan
    if not math.isfinite(value):
        shown = "missing" if text is None else f"not a number: {text!r}"
        raise PlanFormatError(path, f"{what} is {shown}", element)
    return value


def point(el: ET.Element, path: Path, element: str) -> tuple[float, float]:
    """The ``x``/``y`` attributes of a ``<point>`` element, in pixels."""
    return (number(el.get("x"), path, element, "x"), number(el.get("y"), path, element, "y"))


def points(parent: ET.Element | None, path: Path, element: str) -> list[tuple[float, float]]:
    """The ``<point>`` children of ``parent`` (empty if ``parent`` is ``None``)."""
    if parent is None:
        return []
    return [point(p, path, f"{element} point {i + 1}") for i, p in enumerate(parent.findall("point"))]


def read_scale(root: ET.Element, path: Path) -> tuple[float, float]:
    """The scale as ``(represented pixels, real length in metres)``.

    Coordinates in metres are ``pixels * real_m / represented_px`` (multiplying first keeps a
    1 px = 1 cm file exact to the last bit).

    Raises:
        PlanFormatError: If ``<scale>`` is missing, a value is not a positive number, or a unit
            is unknown.
    """
    scale = root.find("scale")
    if scale is None:
        raise PlanFormatError(
            path, f"no <scale>: the plan's size in metres is unknown; {_SCALE_HELP}", "scale"
        )
    rep = _positive(scale, "represented_distance", path)
    real = _positive(scale, "real_distance", path)
    rep_unit = (scale.findtext("represented_distance/um") or "pixel").strip().lower()
    if rep_unit not in PIXEL_UNITS:
        raise PlanFormatError(
            path,
            f"unit {rep_unit!r} is not pixels; coordinates are in pixels",
            "scale/represented_distance/um",
        )
    unit = (scale.findtext("real_distance/um") or "").strip().lower()
    if unit not in UNIT_M:
        raise PlanFormatError(
            path, f"unknown unit {unit!r}; known units: {', '.join(UNIT_M)}", "scale/real_distance/um"
        )
    return rep, real * UNIT_M[unit]


def _positive(scale: ET.Element, name: str, path: Path) -> float:
    element = f"scale/{name}/value"
    value = number(scale.findtext(f"{name}/value"), path, element, "the value")
    if value <= 0:
        raise PlanFormatError(path, f"must be a positive number, not {value:g}; {_SCALE_HELP}", element)
    return value
