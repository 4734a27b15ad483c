"""3D worlds of a building for robot simulators and engines: Gazebo, MuJoCo, glTF and OBJ meshes.

``save(building, "office.sdf")`` (or ``.world``, ``.mjcf.xml``, ``.glb``, ``.obj``) picks the
writer; :class:`WorldOptions` (wall height and thickness, door height, open or closed
entrances) is passed as ``options=`` or as its fields (``save(b, "office.sdf",
wall_height_m=3.0)``). Every export uses the plan's frame: metres, the plan's x and y, z up.
"""

from realistic_indoor.io.world3d.scene import Box, WorldOptions, building_boxes

__all__ = ["Box", "WorldOptions", "building_boxes"]
