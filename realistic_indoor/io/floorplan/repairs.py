"""The record of what the reader changed in a plan file, and the warning it gives for defects.

Two kinds of change are recorded, both as ``{"element", "problem", "action"}`` entries of the
building's ``metadata["repairs"]``:

- clean-ups of one outline or portal (zero-area spikes, slivers, a portal without a segment):
  recorded only;
- defects, where the file contradicts itself (inconsistent portals, a door off its rooms'
  walls, overlapping outlines): recorded, with ``"defect"`` naming the kind, and reported as
  a :class:`PlanRepairWarning`; with ``strict=True`` the reader refuses the file instead.
"""

from __future__ import annotations

import warnings
from pathlib import Path

from realistic_indoor.errors import PlanFormatError, PlanRepairWarning

__all__ = ["DEFECTS", "PlanRepairWarning", "RepairLog"]

DEFECTS = ("targets_differ", "one_sided_portal", "door_off_wall", "overlap")
"""Kinds of defect the reader repairs (and refuses under ``strict``)."""


class RepairLog:
    """Collects the repairs made while reading one file.

    Args:
        path: The file being read (named in every message).
        strict: Refuse defects (raise) instead of repairing them.

    Attributes:
        entries: The repairs, in the order they were made.
    """

    def __init__(self, path: Path, strict: bool = False) -> None:
        self.path = path
        self.strict = strict
        self.entries: list[dict[str, str]] = []

    def note(self, element: str, problem: str, action: str) -> None:
        """Record a clean-up (no warning, allowed under ``strict``)."""
        self.entries.append({"element": element, "problem": problem, "action": action})

    def defect(self, kind: str, element: str, problem: str, action: str) -> None:
        """Record a defect and warn, or raise under ``strict``.

        Args:
            kind: One of :data:`DEFECTS`.
            element: The elements concerned, e.g. ``portal linesegment="p1"``.
            problem: What is wrong, without a final full stop.
            action: What the reader does about it (said in the strict error as what it would do).

        Raises:
            PlanFormatError: Under ``strict``: the problem, how to fix it and the repair refused.
        """
        if kind not in DEFECTS:
            raise ValueError(f"unknown defect kind {kind!r}")
        if self.strict:
            raise PlanFormatError(
                self.path,
                f"{problem}; fix the file, or read it without strict (repair: {action})",
                element,
            )
        self.entries.append({"element": element, "problem": problem, "action": action, "defect": kind})
        warnings.warn(PlanRepairWarning(f"{self.path}: {element}: {problem}; {action}"), stacklevel=2)
