"""Reward terms: named physical quantities per step, weighted by the config into the reward."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from realistic_indoor.errors import ConfigError

__all__ = ["RewardWeights", "reward_terms", "term_weights", "weighted_sum"]


@dataclass(frozen=True)
class RewardWeights:
    """Weight of each reward term; the reward is the weighted sum of the terms of a step.

    Attributes:
        new_area: Per square metre of floor newly observed in the robot's map (1/m2).
        collision: Per control step in which the robot touched a wall.
        time: Per control step (a small cost makes fast exploration pay).
        victim: Per victim newly found (search environments only).
    """

    new_area: float = 0.1
    collision: float = -0.5
    time: float = -0.01
    victim: float = 5.0

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                raise ConfigError(f"RewardWeights.{f.name} must be a finite number, got {value!r}")


def reward_terms(new_area_m2: float, collided: bool, victims_found: int | None = None) -> dict[str, float]:
    """The unweighted reward terms of one step, as returned in ``info["rewards"]``.

    Args:
        new_area_m2: Floor area newly observed in this step (m2).
        collided: Whether the robot touched a wall in this step.
        victims_found: Victims found in this step; ``None`` in environments without victims
            (the term is then left out).

    Returns:
        ``{"new_area": m2, "collision": 0 or 1, "time": 1}`` plus ``"victim": count``.
    """
    terms = {"new_area": float(new_area_m2), "collision": float(collided), "time": 1.0}
    if victims_found is not None:
        terms["victim"] = float(victims_found)
    return terms


def weighted_sum(weights: RewardWeights, terms: Mapping[str, Any]) -> Any:
    """The reward: the sum of each term times its weight, in the order of ``terms``.

    Terms that are floats give a float; terms that are arrays give an array, summed in the same
    order, hence the same values. The native vector environment sums :func:`term_weights` in
    this order in compiled code (``envs/_vector_kernels.py``: ``account``).
    """
    total = sum(getattr(weights, name) * value for name, value in terms.items())
    return float(total) if np.ndim(total) == 0 else total


def term_weights(weights: RewardWeights, names: Sequence[str]) -> np.ndarray:
    """``(len(names),)`` float64 weights of the terms ``names``, in that order (for compiled sums)."""
    return np.array([float(getattr(weights, name)) for name in names])
