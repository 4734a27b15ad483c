"""The room toolkit: what every layout of offices and schools does once its footprint is painted.

A layout (:mod:`~realistic_indoor.generator.blocks`, :mod:`~realistic_indoor.generator.wings`)
paints its footprint into :class:`~realistic_indoor.generator.rooms.regions.FloorRegions`;
these modules make a building of them:

- :mod:`~realistic_indoor.generator.rooms.regions`: the painted regions (``FloorRegions``) and
  a strip of rooms along a corridor (``Bay``);
- :mod:`~realistic_indoor.generator.rooms.dims`: building-wide sizes (corridor width, strip
  depths) drawn from the model;
- :mod:`~realistic_indoor.generator.rooms.from_regions`: rooms from the regions: halls, strips
  cut into rooms (:mod:`~realistic_indoor.generator.rooms.bays`, with the counts of
  :mod:`~realistic_indoor.generator.rooms.budget`), rooms set into halls
  (:mod:`~realistic_indoor.generator.rooms.halls`), corridor segments
  (:mod:`~realistic_indoor.generator.rooms.corridors`);
- :mod:`~realistic_indoor.generator.rooms.annex`: large rooms beside the building (a school's
  gym, an auditorium, a canteen);
- :mod:`~realistic_indoor.generator.rooms.suites`,
  :mod:`~realistic_indoor.generator.rooms.entrances` and
  :mod:`~realistic_indoor.generator.rooms.connect_and_name`: doors and functions.
"""
