"""The rules the learned explorer can be cloned from: classical explorers' choices, in candidate features.

A rule scores each candidate goal of a decision from its ``candidates`` row and takes the
lowest score; a detected victim (always candidate 0 when there is one) comes first. Each is a
classical explorer's rule restricted to the K candidates (a goal farther than the K-th nearest
frontier is not offered):

* ``frontier``: the smallest path cost (the nearest-frontier explorer: always candidate 0);
* ``structure``: the path cost, a frontier off the corridors and halls counting the structure
  explorer's ``room_factor`` (4) times (:class:`~realistic_indoor.agents.structure.StructureAgent`);
* ``utility``: ``3 * path cost - frontier length`` (ROS explore_lite's weights, the utility
  explorer's defaults, :class:`~realistic_indoor.agents.utility.UtilityFrontierAgent`);
* ``structure-utility``: the utility rule with a room frontier's cost counted twice;
* ``structure-utility-area``: ``structure-utility`` with a second gain, the unobserved area
  near the frontier (the utility explorer's ``"area"`` gain), weighted 2 per 10 m2 against 3 per
  10 m of path (a m2 unseen is worth about 0.7 m of travel): chosen on the tuning seeds as the
  registered rule that leads the nearest frontier in houses too, where the others trail it;
* ``structure-utility-area-short``: ``structure-utility-area`` with the cost of a frontier
  shorter than 1 m counted twice (a sliver in a corner or behind a door frame is left for
  later unless nothing longer is near): chosen on the tuning seeds, where it leads the nearest
  frontier in schools by 0.016 against the former's 0.010 (30 seeds) and is level with the
  former in offices and houses (``experiments/teacher_rules.py``);
* ``gain``: the path cost less twice the unobserved area near the frontier (no structure, no
  frontier length): the best of the rules tried in houses on the tuning seeds (+0.009 [+0.002,
  +0.017] over the nearest frontier on 60 houses, where ``structure-utility-area-short`` stands
  at -0.001), and far behind it in schools, so the recipe clones it in houses only
  (:attr:`~realistic_indoor.agents.rl.learned.LearnedConfig.teacher_by_id`).

:class:`TeacherPolicy` runs a rule where a trained model would (``make_agent("learned", env,
model=TeacherPolicy("utility"))``), so a rule is evaluated on the same candidates the policy sees.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from realistic_indoor.errors import ConfigError

__all__ = ["DEFAULT_TEACHER", "TEACHERS", "TeacherPolicy", "TeacherRule", "teacher_choice"]


@dataclass(frozen=True)
class TeacherRule:
    """A candidate's score, the lowest taken.

    ``cost_weight * path_cost * (room_factor if in a room) * (short_factor if shorter than
    short_m) - length_weight * size - gain_weight * unobserved + turn_weight * (1 -
    cos_bearing) / 2``, in the ``candidates`` observation's units.

    Attributes:
        cost_weight: Weight of the path cost (per 10 m of clear floor, the feature's unit).
        room_factor: Factor on the cost of a frontier off the corridors and halls.
        length_weight: Weight of the frontier's length (per 10 m).
        gain_weight: Weight of the unobserved area near the frontier (per 10 m2).
        turn_weight: Score added for a goal straight behind the robot's heading (half of it for
            one abeam, none ahead; the straight-line bearing, not the path's first leg), in the
            score's units: ``turn_weight / cost_weight`` times 10 m of path. A preference for
            keeping on, against back-tracking; no registered rule uses it (tried on the tuning
            seeds, see ``experiments/teacher_rules.py``).
        short_factor: Factor on the cost of a frontier shorter than ``short_m``: a sliver left
            in a corner or behind a door frame, worth going back to only when nothing longer is
            near (it multiplies with ``room_factor``).
        short_m: Frontiers shorter than this take ``short_factor`` (m; the ``size`` feature
            times 10).
    """

    cost_weight: float = 1.0
    room_factor: float = 1.0
    length_weight: float = 0.0
    gain_weight: float = 0.0
    turn_weight: float = 0.0
    short_factor: float = 1.0
    short_m: float = 1.0

    def choose(self, candidates: np.ndarray, mask: np.ndarray) -> int:
        """The candidate this rule takes.

        Args:
            candidates: The ``candidates`` observation (flat, ``K * F``).
            mask: ``(K,)`` bool, the candidates that exist.
        """
        from realistic_indoor.envs.macro import CANDIDATE_FEATURES as F
        from realistic_indoor.envs.macro import LENGTH_UNIT_M

        rows = np.asarray(candidates, dtype=float).reshape(len(mask), len(F))
        if rows[0, F.index("victim")] > 0.5:
            return 0
        factor = np.where(rows[:, F.index("in_room")] > 0.5, self.room_factor, 1.0)
        short = rows[:, F.index("size")] * LENGTH_UNIT_M < self.short_m
        factor = factor * np.where(short, self.short_factor, 1.0)
        score = self.cost_weight * rows[:, F.index("path_cost")] * factor
        score = score - self.length_weight * rows[:, F.index("size")]
        score = score - self.gain_weight * rows[:, F.index("unobserved")]
        score = score + self.turn_weight * (1.0 - rows[:, F.index("cos_bearing")]) / 2.0
        return int(np.argmin(np.where(mask, score, np.inf)))


TEACHERS: dict[str, TeacherRule] = {
    "frontier": TeacherRule(),
    "structure": TeacherRule(room_factor=4.0),
    "utility": TeacherRule(cost_weight=3.0, length_weight=1.0),
    "structure-utility": TeacherRule(cost_weight=3.0, room_factor=2.0, length_weight=1.0),
    "structure-utility-area": TeacherRule(
        cost_weight=3.0, room_factor=2.0, length_weight=1.0, gain_weight=2.0
    ),
    "structure-utility-area-short": TeacherRule(
        cost_weight=3.0, room_factor=2.0, length_weight=1.0, gain_weight=2.0, short_factor=2.0, short_m=1.0
    ),
    "gain": TeacherRule(gain_weight=2.0),
}
"""The named rules (see the module's docstring)."""

DEFAULT_TEACHER = "structure-utility-area-short"
"""The rule the learned explorer's recipe clones (:attr:`~realistic_indoor.agents.rl.learned.LearnedConfig.teacher`)."""


def teacher_choice(candidates: np.ndarray, mask: np.ndarray, teacher: str = "structure") -> int:
    """The candidate the rule ``teacher`` of :data:`TEACHERS` takes.

    Raises:
        ConfigError: For an unknown rule.
    """
    return _rule(teacher).choose(candidates, mask)


def _rule(name: str) -> TeacherRule:
    if name not in TEACHERS:
        raise ConfigError(f"unknown teacher {name!r}; rules: {', '.join(TEACHERS)}")
    return TEACHERS[name]


class _Actions:
    """The stand-in of a model's ``action_space``: its number of actions, K."""

    def __init__(self, n: int) -> None:
        self.n = n


class TeacherPolicy:
    """A rule of :data:`TEACHERS` behind a trained model's ``predict``, for the learned agent.

    Args:
        teacher: The rule's name in :data:`TEACHERS`, or a :class:`TeacherRule` (one not
            registered, as ``experiments/teacher_rules.py --extra`` runs).
        n_candidates: K.
    """

    def __init__(self, teacher: str | TeacherRule = "structure", n_candidates: int = 16) -> None:
        self.rule = teacher if isinstance(teacher, TeacherRule) else _rule(teacher)
        self.teacher = teacher
        self.action_space = _Actions(n_candidates)

    def predict(
        self, obs: dict[str, np.ndarray], action_masks: np.ndarray, deterministic: bool = True
    ) -> tuple[int, Any]:
        """The rule's choice at one decision (``deterministic`` is ignored: a rule has one)."""
        return self.rule.choose(obs["candidates"], np.asarray(action_masks, dtype=bool)), None

    def __repr__(self) -> str:
        return f"TeacherPolicy({self.teacher!r})"
