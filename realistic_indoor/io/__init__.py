"""Reading and writing buildings: JSON, floor-plan XML, World Generator XML, ROS maps, pictures, 3D worlds.

``load(path)`` and ``save(building, path)`` choose the format from the file name.
"""

from realistic_indoor.io.registry import FORMATS, format_of, load, save

__all__ = ["FORMATS", "format_of", "load", "save"]
