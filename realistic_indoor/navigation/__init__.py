"""Navigation on the robot's own map: the layer between the simulator and the environments.

What a map-based explorer does below choosing where to go, in one home that the explorers
(:mod:`realistic_indoor.agents`) and the environments' macro actions (:mod:`realistic_indoor.envs`)
share:

- :mod:`~realistic_indoor.navigation.spec`: the robot's datasheet (:class:`RobotSpec`) and the
  discrete action set;
- :mod:`~realistic_indoor.navigation.own_map`: the global occupancy grid built from scans and
  odometry (:class:`OwnMap`);
- :mod:`~realistic_indoor.navigation.frontiers`, :mod:`~realistic_indoor.navigation.goals`:
  frontiers, the nearest one, the path cost to each;
- :mod:`~realistic_indoor.navigation.planning`: costmap, Dijkstra, paths;
- :mod:`~realistic_indoor.navigation.follower`: pure pursuit along a path;
- :mod:`~realistic_indoor.navigation.reflexes`: bumps, jams, being stuck, backing up;
- :mod:`~realistic_indoor.navigation.regions`: corridors, halls and rooms on the map;
- :mod:`~realistic_indoor.navigation.victims`: victims detected, in the odometry frame;
- :mod:`~realistic_indoor.navigation.navigator`: the loop (:class:`Navigator`) that ties them.

See ``docs/agents.md``.
"""
