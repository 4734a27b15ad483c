"""Errors raised for bad user input: each says what is wrong and how to fix it."""

from __future__ import annotations

__all__ = ["ActionError", "ConfigError", "PlanFormatError", "PlanRepairWarning", "RealisticIndoorError"]


class RealisticIndoorError(ValueError):
    """Base class of every error caused by user input (files, arguments, configs).

    The command line prints these as one line without a traceback; anything else is a bug.
    """


class PlanFormatError(RealisticIndoorError):
    """A plan file cannot be read: missing, malformed, or holding an invalid element.

    Args:
        path: The file that was being read.
        message: What is wrong, and how to fix it where that is not obvious.
        element: The element of the file where the problem is (e.g. ``space id="3"``).
    """

    def __init__(self, path: object, message: str, element: str | None = None) -> None:
        self.path = str(path)
        self.element = element
        self.reason = message
        where = f"{self.path}: {element}" if element else self.path
        super().__init__(f"{where}: {message}")


class ConfigError(RealisticIndoorError):
    """A configuration value or argument is invalid (unknown type, negative range, ...)."""


class ActionError(RealisticIndoorError):
    """An action given to an environment's ``step`` is not in its action space.

    Raised for non-finite or wrongly shaped continuous actions and for discrete actions that
    are not integers in range; the message names the action given and what is allowed.
    """


class PlanRepairWarning(UserWarning):
    """A plan contradicted itself or held an invalid outline, and was repaired by a documented rule.

    The message is one line naming the file, the element concerned, what was wrong and what was
    done. Reading with ``strict=True`` raises a :class:`PlanFormatError` instead. The rules are
    in ``docs/formats.md`` (floor-plan XML) and ``docs/failures.md`` (every plan).
    """
