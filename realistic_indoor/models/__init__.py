"""Building-type models: the paper's reference statistics, and models fitted to real plans."""

from realistic_indoor.models.building_model import (
    BuildingTypeModel,
    LabelStats,
    LocalStructures,
    default_model,
    real_model,
)
from realistic_indoor.models.fit import fit_model
from realistic_indoor.models.reference import REFERENCE_SETS, connectivity_facts, reference_table

__all__ = [
    "REFERENCE_SETS",
    "BuildingTypeModel",
    "LabelStats",
    "LocalStructures",
    "connectivity_facts",
    "default_model",
    "fit_model",
    "real_model",
    "reference_table",
]
