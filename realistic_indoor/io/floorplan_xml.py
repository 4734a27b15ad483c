"""Floor-plan XML, the format of the shared real plans: the registry's entry point.

See :mod:`realistic_indoor.io.floorplan` for the reader and writer.
"""

from realistic_indoor.io.floorplan.reader import read
from realistic_indoor.io.floorplan.writer import write

__all__ = ["read", "write"]
