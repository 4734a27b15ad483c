"""Houses with a house's programme: the table of rooms by floor area, its layout, doors and labels.

- :mod:`~realistic_indoor.generator.house.programme`: the rooms of a house drawn for its floor
  area from the programme table and room sizes of
  :mod:`realistic_indoor.models.house_programme` (the tables of docs/generator.md, with their
  sources);
- :mod:`~realistic_indoor.generator.house.layout`: the footprint cut into a day zone, an
  entrance, hallways and bands of rooms;
- :mod:`~realistic_indoor.generator.house.bands`: rooms side by side along a hallway;
- :mod:`~realistic_indoor.generator.house.rooms`: the rooms put on the plan;
- :mod:`~realistic_indoor.generator.house.doors`: front door, day rooms, night rooms;
- :mod:`~realistic_indoor.generator.house.steps`: these as the steps of the layout template
  (:mod:`~realistic_indoor.generator.template`): the programme fitted to a frame (rooms left
  out until one fits), rooms, doors and size labels;
- :mod:`~realistic_indoor.generator.house.generator`: :class:`HouseGenerator`, which lays a
  house out in those steps.
"""

from realistic_indoor.generator.house.generator import MAX_AREA_M2, MIN_AREA_M2, HouseGenerator

__all__ = ["MAX_AREA_M2", "MIN_AREA_M2", "HouseGenerator"]
