"""Building-type models: the paper's reference statistics, and models fitted to real plans."""

from realistic_indoor.models.reference import REFERENCE_SETS, connectivity_facts, reference_table

__all__ = ["REFERENCE_SETS", "connectivity_facts", "reference_table"]
