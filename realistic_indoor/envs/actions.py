"""Action spaces: how an agent's action becomes a velocity command ``(v, w)`` for the robot."""

from __future__ import annotations

import numpy as np
from gymnasium import spaces

__all__ = ["ACTION_TYPES", "DISCRETE_ACTIONS", "ActionMap"]

ACTION_TYPES = ("continuous", "discrete")
"""Names accepted by :attr:`EnvConfig.action_type`."""

DISCRETE_ACTIONS: tuple[tuple[str, float, float], ...] = (
    ("forward", 1.0, 0.0),
    ("forward-left", 0.5, 0.5),
    ("forward-right", 0.5, -0.5),
    ("turn-left", 0.0, 1.0),
    ("turn-right", 0.0, -1.0),
    ("back", -0.5, 0.0),
)
"""The discrete action set: name, linear and angular velocity as fractions of the limits."""


class ActionMap:
    """The action space of an environment and the map from its actions to velocity commands.

    A continuous action ``a`` in ``Box(-1, 1, (2,))`` commands ``v = a[0] * max_speed_m_s`` and
    ``w = a[1] * max_turn_rad_s`` (values outside ``[-1, 1]`` are clipped); a discrete action
    ``k`` commands the ``k``-th entry of :data:`DISCRETE_ACTIONS` scaled the same way.

    Args:
        action_type: ``"continuous"`` or ``"discrete"``.
        max_speed_m_s: Linear speed of a full action (m/s).
        max_turn_rad_s: Turn rate of a full action (rad/s).

    Attributes:
        space: The Gymnasium action space.
    """

    def __init__(self, action_type: str, max_speed_m_s: float, max_turn_rad_s: float) -> None:
        self._v_max = float(max_speed_m_s)
        self._w_max = float(max_turn_rad_s)
        self.discrete = action_type == "discrete"
        if self.discrete:
            self._table = [(v * self._v_max, w * self._w_max) for _, v, w in DISCRETE_ACTIONS]
            self.space: spaces.Space = spaces.Discrete(len(DISCRETE_ACTIONS))
        else:
            self.space = spaces.Box(-1.0, 1.0, (2,), np.float32)

    def command(self, action: np.ndarray | int) -> tuple[float, float]:
        """The velocity command ``(v m/s, w rad/s)`` of ``action``."""
        if self.discrete:
            return self._table[int(action)]
        a, b = (float(x) for x in np.ravel(action))
        return max(-1.0, min(1.0, a)) * self._v_max, max(-1.0, min(1.0, b)) * self._w_max
