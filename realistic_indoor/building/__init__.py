"""The data model: ``Building``, ``Room``, ``Door``, labels, topology, walls and checks.

Buildings from outside the package pass one gate, :func:`admit_building`.
"""

from realistic_indoor.building.admit import admit_building
from realistic_indoor.building.building import Building
from realistic_indoor.building.check import Finding, InvalidBuildingError, check_building
from realistic_indoor.building.door import Door
from realistic_indoor.building.labels import (
    CIRCULATION_LABELS,
    ROOM_LABELS,
    BuildingType,
    SemanticLabel,
    parse_building_type,
    parse_label,
)
from realistic_indoor.building.room import Room

__all__ = [
    "CIRCULATION_LABELS",
    "ROOM_LABELS",
    "Building",
    "BuildingType",
    "Door",
    "Finding",
    "InvalidBuildingError",
    "Room",
    "SemanticLabel",
    "admit_building",
    "check_building",
    "parse_building_type",
    "parse_label",
]
