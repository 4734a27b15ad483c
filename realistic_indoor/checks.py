"""Validation of configuration values: one clear ``ConfigError`` per bad value.

The config dataclasses of the simulator, the environments and the agents call these from
``__post_init__``, so a bad value fails where it is set, naming the class, the field, the value
given and the range allowed. Physical settings take :func:`require_between`: a plausible range,
not only a sign (a robot of radius 100 m is refused rather than simulated); the ranges are listed
in ``docs/failures.md``, section "Plausible bounds".
"""

from __future__ import annotations

import math
from numbers import Integral, Real

from realistic_indoor.errors import ConfigError

__all__ = ["require_between", "require_bool", "require_int", "require_positive", "require_range"]


def require_positive(owner: str, name: str, value: float, unit: str, allow_zero: bool = False) -> None:
    """Raise ``ConfigError`` unless ``value`` is a finite number > 0 (>= 0 with ``allow_zero``)."""
    ok = isinstance(value, Real) and math.isfinite(value) and (value >= 0 if allow_zero else value > 0)
    if not ok:
        bound = ">= 0" if allow_zero else "> 0"
        raise ConfigError(f"{owner}.{name} must be a finite number {bound} {unit}, got {value!r}".rstrip())


def require_int(owner: str, name: str, value: int, minimum: int, maximum: int | None = None) -> None:
    """Raise ``ConfigError`` unless ``value`` is an integer >= ``minimum`` (and <= ``maximum``).

    Args:
        owner: The class or function the value belongs to (``""``: ``name`` alone, e.g. a flag).
        name: The field.
        value: The value given; a bool is refused.
        minimum: The smallest value allowed.
        maximum: The largest value allowed; ``None``: no upper bound.

    Raises:
        ConfigError: ``"RobotConfig.substeps must be an integer in [1, 1000], got 0"``, or
            ``"... must be an integer >= 1, got 0"`` without ``maximum``.
    """
    bad = isinstance(value, bool) or not isinstance(value, Integral) or value < minimum
    if maximum is None:
        if bad:
            raise ConfigError(f"{_label(owner, name)} must be an integer >= {minimum}, got {value!r}")
    elif bad or value > maximum:
        raise ConfigError(
            f"{_label(owner, name)} must be an integer in [{minimum}, {maximum}], got {value!r}"
        )


def require_bool(owner: str, name: str, value: bool) -> None:
    """Raise ``ConfigError`` unless ``value`` is ``True`` or ``False`` (a string ``"false"`` is refused)."""
    if not isinstance(value, bool):
        raise ConfigError(f"{_label(owner, name)} must be True or False, got {value!r}")


def require_range(owner: str, name: str, value: float, low: float, high: float, unit: str) -> None:
    """Raise ``ConfigError`` unless ``low < value <= high``."""
    if not (isinstance(value, Real) and low < value <= high):
        raise ConfigError(f"{owner}.{name} must be in ({low:g}, {high:g}] {unit}, got {value!r}")


def require_between(
    owner: str,
    name: str,
    value: float,
    low: float,
    high: float,
    unit: str,
    *,
    low_open: bool = False,
) -> None:
    """Raise ``ConfigError`` unless ``value`` is a finite number in ``[low, high]``.

    Args:
        owner: The class or function the value belongs to (``""``: ``name`` alone, e.g. a flag).
        name: The field.
        value: The value given; NaN, infinities, bools and non-numbers are refused.
        low: The smallest value allowed (in the unit).
        high: The largest value allowed (in the unit).
        unit: The unit, as the message writes it (``"m"``, ``"m/s"``; ``""`` for a share).
        low_open: Refuse ``low`` itself: the range is ``(low, high]``.

    Raises:
        ConfigError: One line naming the field, the range and the value, e.g.
            ``"RobotConfig.radius_m must be a finite number in [0.05, 2] m, got 100.0"``.
    """
    ok = (
        isinstance(value, Real)
        and not isinstance(value, bool)
        and math.isfinite(value)
        and (low < value if low_open else low <= value)
        and value <= high
    )
    if not ok:
        span = f"{'(' if low_open else '['}{_number(low)}, {_number(high)}]" + (f" {unit}" if unit else "")
        raise ConfigError(f"{_label(owner, name)} must be a finite number in {span}, got {value!r}")


def _label(owner: str, name: str) -> str:
    """``owner.name``, or ``name`` alone for an empty owner."""
    return f"{owner}.{name}" if owner else name


def _number(x: float) -> str:
    """A bound as the messages write it: ``2``, ``0.05``, ``50000``, ``6.28319``."""
    return str(int(x)) if float(x).is_integer() and abs(x) < 1e15 else f"{x:g}"
