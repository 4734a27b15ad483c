"""Action spaces: how an agent's action becomes a velocity command ``(v, w)`` for the robot."""

from __future__ import annotations

import math

import numpy as np
from gymnasium import spaces

from realistic_indoor.errors import ActionError
from realistic_indoor.navigation.spec import DISCRETE_ACTIONS

__all__ = ["ACTION_TYPES", "DISCRETE_ACTIONS", "PRIMITIVE_ACTION_TYPES", "ActionMap", "discrete_index"]

PRIMITIVE_ACTION_TYPES = ("continuous", "discrete")
"""Action types whose action is a velocity command (:class:`ActionMap`)."""
ACTION_TYPES = (*PRIMITIVE_ACTION_TYPES, "frontier", "waypoint")
"""Names accepted by :attr:`EnvConfig.action_type`; ``"frontier"`` and ``"waypoint"`` choose a goal
(:mod:`realistic_indoor.envs.macro`)."""

_NAMES = ", ".join(name for name, _, _ in DISCRETE_ACTIONS)


class ActionMap:
    """The action space of an environment and the map from its actions to velocity commands.

    A continuous action ``a`` in ``Box(-1, 1, (2,))`` commands ``v = a[0] * max_speed_m_s`` and
    ``w = a[1] * max_turn_rad_s``. Finite values outside ``[-1, 1]`` are clipped to it (a
    policy's raw Gaussian output is fine); NaN and infinities are refused, as is any shape
    but ``(2,)``. A discrete action ``k`` commands the ``k``-th entry of
    :data:`DISCRETE_ACTIONS` scaled the same way; ``k`` must be an integer in ``0..5`` (a
    Python or NumPy integer, or a 0-d integer array); floats and booleans are refused rather
    than rounded.

    Args:
        action_type: ``"continuous"`` or ``"discrete"``.
        max_speed_m_s: Linear speed of a full action (m/s).
        max_turn_rad_s: Turn rate of a full action (rad/s).

    Attributes:
        space: The Gymnasium action space.
        discrete: Whether the actions are discrete.
        table: ``(6, 2)`` velocity commands (m/s, rad/s) of the discrete actions, in order.
        limits: ``(2,)`` the commands of a full continuous action, ``(max_speed_m_s, max_turn_rad_s)``.
    """

    def __init__(self, action_type: str, max_speed_m_s: float, max_turn_rad_s: float) -> None:
        self._v_max = float(max_speed_m_s)
        self._w_max = float(max_turn_rad_s)
        self.discrete = action_type == "discrete"
        self.limits = np.array([self._v_max, self._w_max])
        self.table = np.array([(v * self._v_max, w * self._w_max) for _, v, w in DISCRETE_ACTIONS])
        self._table = [tuple(row) for row in self.table.tolist()]
        if self.discrete:
            self.space: spaces.Space = spaces.Discrete(len(DISCRETE_ACTIONS))
        else:
            self.space = spaces.Box(-1.0, 1.0, (2,), np.float32)

    def commands(self, actions: object, n: int) -> np.ndarray:
        """The velocity commands of a batch of ``n`` actions, one per robot (the vector env's step).

        Args:
            actions: ``(n,)`` integers in ``0..5`` (discrete) or a finite ``(n, 2)`` array of
                ``(linear, turn)`` (continuous; values outside ``[-1, 1]`` are clipped).
            n: The number of robots.

        Returns:
            ``(n, 2)`` commands: linear velocity (m/s) and turn rate (rad/s).

        Raises:
            ActionError: If the batch has another shape, or holds an action outside the space.
        """
        a = np.asarray(actions)
        if self.discrete:
            if a.shape != (n,) or a.dtype.kind not in "iu" or ((a < 0) | (a >= len(self.table))).any():
                raise ActionError(
                    f"actions must be {n} integers in 0..{len(self.table) - 1}, got {actions!r}"
                )
            return self.table[a]
        if a.shape != (n, 2) or a.dtype.kind not in "fiu" or not np.isfinite(a).all():
            raise ActionError(
                f"actions must be a finite ({n}, 2) array of (linear, turn) in [-1, 1], got {a.dtype} {a.shape}"
            )
        return np.minimum(np.maximum(a, -1.0), 1.0) * self.limits  # np.clip's values, a third of its cost

    def command(self, action: np.ndarray | int) -> tuple[float, float]:
        """The velocity command of ``action``.

        Args:
            action: A continuous action (2 numbers, ``(linear, turn)`` in ``[-1, 1]``) or a
                discrete action (an integer in ``0..5``).

        Returns:
            ``(v, w)``: linear velocity (m/s) and turn rate (rad/s, counter-clockwise).

        Raises:
            ActionError: If the action is not in the action space: a continuous action that is
                not of shape ``(2,)``, not numeric, NaN or infinite; a discrete action that is
                not an integer or not in ``0..5``.
        """
        if self.discrete:
            if type(action) is int and 0 <= action < len(self._table):
                return self._table[action]  # the common case, fast
            return self._table[discrete_index(action, len(self._table), "discrete action", _NAMES)]
        if type(action) is np.ndarray and action.shape == (2,) and action.dtype.kind == "f":
            a, b = action.tolist()  # the common case, fast: Python floats without NumPy scalars
        else:
            a, b = self._pair(action)
        if not (math.isfinite(a) and math.isfinite(b)):
            raise ActionError(
                f"continuous action must be 2 finite numbers (linear, turn) in [-1, 1], got {action!r}; "
                "NaN and infinite values are refused (finite values outside [-1, 1] are clipped)"
            )
        return max(-1.0, min(1.0, a)) * self._v_max, max(-1.0, min(1.0, b)) * self._w_max

    @staticmethod
    def _pair(action: object) -> tuple[float, float]:
        """``(a[0], a[1])`` as floats of a continuous action of shape ``(2,)``."""
        shape = _shape(action)
        if shape != (2,):
            given = repr(action) if shape is None else f"shape {shape}"
            raise ActionError(
                f"continuous action must have shape (2,) (linear, turn commands in [-1, 1]), got {given}"
            )
        try:
            return float(action[0]), float(action[1])
        except (TypeError, ValueError):
            raise ActionError(
                f"continuous action must be 2 numbers (linear, turn) in [-1, 1], got {action!r}"
            ) from None


def discrete_index(action: object, n: int, what: str, names: str) -> int:
    """A discrete action as an ``int`` in ``0..n-1``: a Python or NumPy integer, or a 0-d integer array.

    Floats and booleans are refused rather than rounded.

    Args:
        action: The action.
        n: Number of actions.
        what: What the action is, for the message (``"discrete action"``).
        names: What the actions mean, for the message (``"forward, forward-left, ..."``).

    Raises:
        ActionError: If ``action`` is not an integer, or not in ``0..n-1``.
    """
    if (isinstance(action, (int, np.integer)) and not isinstance(action, (bool, np.bool_))) or (
        isinstance(action, np.ndarray) and action.shape == () and action.dtype.kind in "iu"
    ):
        k = int(action)
    else:
        raise ActionError(
            f"{what} must be an integer in 0..{n - 1} ({names}), got {action!r} of type {type(action).__name__}"
        )
    if not 0 <= k < n:
        raise ActionError(f"{what} must be in 0..{n - 1} ({names}), got {k}")
    return k


def _shape(action: object) -> tuple[int, ...] | str | None:
    """The array shape of a sequence or array; ``"ragged"`` for nested lists of uneven length."""
    if not isinstance(action, (np.ndarray, list, tuple)):
        return None  # a scalar, a string, None: no shape to report
    try:
        return np.shape(action)
    except ValueError:
        return "ragged"
