"""Semantic room labels and building types."""

from __future__ import annotations

from enum import Enum

from realistic_indoor.errors import ConfigError

__all__ = [
    "CIRCULATION_LABELS",
    "ROOM_LABELS",
    "BuildingType",
    "SemanticLabel",
    "parse_building_type",
    "parse_label",
]


class SemanticLabel(str, Enum):
    """The paper's five semantic (size) labels of a room."""

    CORRIDOR = "corridor"
    HALL = "hall"
    SMALL = "small"
    MEDIUM = "medium"
    BIG = "big"

    @property
    def letter(self) -> str:
        """One-letter code used by the paper (C, H, S, M, B)."""
        return self.value[0].upper()


ROOM_LABELS: tuple[SemanticLabel, ...] = (
    SemanticLabel.SMALL,
    SemanticLabel.MEDIUM,
    SemanticLabel.BIG,
)
"""Labels of ordinary rooms, as opposed to the circulation spaces (corridor, hall)."""

CIRCULATION_LABELS: tuple[SemanticLabel, ...] = (SemanticLabel.CORRIDOR, SemanticLabel.HALL)
"""Labels of the circulation spaces: corridors and halls, through which people reach rooms."""


class BuildingType(str, Enum):
    """The function a building was designed for."""

    OFFICE = "office"
    SCHOOL = "school"
    HOUSE = "house"
    UNKNOWN = "unknown"


def _parse_enum(enum: type[Enum], value: object, what: str) -> Enum:
    if isinstance(value, enum):
        return value
    text = str(value).strip().lower()
    for member in enum:
        if text in (member.value, member.name.lower()) or (
            enum is SemanticLabel and text == member.letter.lower()
        ):
            return member
    valid = ", ".join(m.value for m in enum)
    raise ConfigError(f"unknown {what} {value!r}; valid values: {valid}")


def parse_label(value: object) -> SemanticLabel:
    """Return the semantic label named by ``value`` (``"corridor"``, ``"C"``, an enum member).

    Raises:
        ConfigError: If ``value`` names no label; the message lists the valid ones.
    """
    return _parse_enum(SemanticLabel, value, "semantic label")  # type: ignore[return-value]


def parse_building_type(value: object) -> BuildingType:
    """Return the building type named by ``value`` (``"office"``, ``BuildingType.SCHOOL``, ...).

    Raises:
        ConfigError: If ``value`` names no type; the message lists the valid ones.
    """
    return _parse_enum(BuildingType, value, "building type")  # type: ignore[return-value]
