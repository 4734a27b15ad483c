"""Validation of configuration values: one clear ``ConfigError`` per bad value.

The config dataclasses of the simulator, the environments and the agents call these from
``__post_init__``, so a bad value fails where it is set, naming the class, the field, the value
given and the range allowed.
"""

from __future__ import annotations

import math
from numbers import Integral, Real

from realistic_indoor.errors import ConfigError

__all__ = ["require_int", "require_positive", "require_range"]


def require_positive(owner: str, name: str, value: float, unit: str, allow_zero: bool = False) -> None:
    """Raise ``ConfigError`` unless ``value`` is a finite number > 0 (>= 0 with ``allow_zero``)."""
    ok = isinstance(value, Real) and math.isfinite(value) and (value >= 0 if allow_zero else value > 0)
    if not ok:
        bound = ">= 0" if allow_zero else "> 0"
        raise ConfigError(f"{owner}.{name} must be a finite number {bound} {unit}, got {value!r}".rstrip())


def require_int(owner: str, name: str, value: int, minimum: int) -> None:
    """Raise ``ConfigError`` unless ``value`` is an integer >= ``minimum``."""
    if isinstance(value, bool) or not isinstance(value, Integral) or value < minimum:
        raise ConfigError(f"{owner}.{name} must be an integer >= {minimum}, got {value!r}")


def require_range(owner: str, name: str, value: float, low: float, high: float, unit: str) -> None:
    """Raise ``ConfigError`` unless ``low < value <= high``."""
    if not (isinstance(value, Real) and low < value <= high):
        raise ConfigError(f"{owner}.{name} must be in ({low:g}, {high:g}] {unit}, got {value!r}")
