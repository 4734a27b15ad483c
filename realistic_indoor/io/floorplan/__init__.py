"""The floor-plan XML format of the real plans (``<building>`` / ``<floor>`` / ``<spaces>``).

:func:`read` builds a :class:`~realistic_indoor.building.Building` in metres from a file,
repairing portals and outlines that contradict each other (each repair a
:class:`PlanRepairWarning`; ``strict=True`` refuses such a file instead); :func:`write` writes
one back (1 px = 1 cm). ``realistic_indoor.io.floorplan_xml`` is the name the format registry
knows; ``docs/formats.md`` describes the format and the repair rules.
"""

from realistic_indoor.io.floorplan.reader import read
from realistic_indoor.io.floorplan.repairs import PlanRepairWarning
from realistic_indoor.io.floorplan.writer import write

__all__ = ["PlanRepairWarning", "read", "write"]
