"""The project's vocabulary of rooms and buildings: labels, functions, building types, the outside.

Every module names these words through this one, so each has one definition.
"""

from __future__ import annotations

from enum import Enum
from typing import TYPE_CHECKING

from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = [
    "CIRCULATION_LABELS",
    "CORE_FUNCTIONS",
    "INFERRED",
    "OUTSIDE",
    "ROOM_LABELS",
    "BuildingType",
    "SemanticLabel",
    "is_core_function",
    "labels_inferred",
    "normalise_function",
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


OUTSIDE = "outside"
"""The outside of a building seen as a room's neighbour: the graph node behind the exterior doors
(``Building.graph(include_outside=True)``) and the neighbour of an exterior door in a model's
connection table. (A :class:`~realistic_indoor.building.door.Door` to the outside has
``room_b=None``; the simulator's raster marks the cells outside the plan ``RASTER_OUTSIDE``.)"""

INFERRED = "inferred"
"""Value of a building's ``metadata["semantic_labels"]`` when its semantic labels were inferred
from the plan's geometry (:func:`realistic_indoor.validator.infer_labels`), not given by it."""


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


CORE_FUNCTIONS: dict[BuildingType, frozenset[str]] = {
    BuildingType.OFFICE: frozenset({"office", "office room", "shared office", "executive office"}),
    BuildingType.SCHOOL: frozenset({"classroom", "class room"}),
    BuildingType.HOUSE: frozenset({"bedroom", "bed room"}),
    BuildingType.UNKNOWN: frozenset(),
}
"""Functional labels (normalised, see :func:`normalise_function`) that are each type's core
function: the rooms the building exists for."""


def normalise_function(name: object) -> str:
    """A functional label in the project's spelling: lower case, ``_`` and ``-`` as spaces, single spaces.

    Examples:
        >>> normalise_function("SHARED_OFFICE")
        'shared office'
        >>> normalise_function("  Open-plan   Office ")
        'open plan office'
    """
    return " ".join(str(name).lower().replace("_", " ").replace("-", " ").split())


def is_core_function(function: str, building_type: BuildingType | str) -> bool:
    """Whether ``function`` is the core function of ``building_type`` (see :data:`CORE_FUNCTIONS`).

    Examples:
        >>> is_core_function("Class_Room", "school"), is_core_function("office", "school")
        (True, False)
    """
    return normalise_function(function) in CORE_FUNCTIONS[parse_building_type(building_type)]


def labels_inferred(building: Building) -> bool:
    """Whether the building's semantic labels were inferred from its geometry (see :data:`INFERRED`)."""
    return building.metadata.get("semantic_labels") == INFERRED
