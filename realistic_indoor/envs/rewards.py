"""Reward terms: named physical quantities per step, weighted by the config into the reward."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.batch import STEP_TERMS

__all__ = [
    "EXPLORE_TERMS",
    "SEARCH_TERMS",
    "RewardWeights",
    "auc_weight",
    "reward_terms",
    "term_weights",
    "weighted_sum",
]

EXPLORE_TERMS = STEP_TERMS
"""The reward terms of exploration, in order: ``new_area``, ``collision``, ``time``."""
SEARCH_TERMS = (*STEP_TERMS, "victim")
"""The reward terms of search: those of exploration, then ``victim`` (victims newly found)."""


@dataclass(frozen=True)
class RewardWeights:
    """Weight of each reward term; the reward is the weighted sum of the terms of a step.

    Attributes:
        new_area: Per square metre of floor newly observed in the robot's map (1/m2).
        collision: Per control step in which the robot touched a wall.
        time: Per control step (a small cost makes fast exploration pay).
        victim: Per victim newly found (search environments only).
        coverage_auc: Per unit of the step's coverage gain weighted by the share of the step
            limit still to come, ``(max_steps + 1 - t) / (max_steps + 1)`` at step ``t``: with
            weight 1 and the others 0 (:meth:`metric`), an episode's undiscounted return is its
            coverage AUC (the evaluation's ``coverage_auc``) minus the coverage at reset. The
            term is in ``info["rewards"]`` only where its weight is not 0; the native vector
            environment refuses it.
    """

    new_area: float = 0.1
    collision: float = -0.5
    time: float = -0.01
    victim: float = 5.0
    coverage_auc: float = 0.0

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                raise ConfigError(f"RewardWeights.{f.name} must be a finite number, got {value!r}")

    @classmethod
    def metric(cls) -> RewardWeights:
        """The reward that is the metric: ``coverage_auc`` alone (weight 1, every other term 0)."""
        return cls(new_area=0.0, collision=0.0, time=0.0, victim=0.0, coverage_auc=1.0)


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
    values = (float(new_area_m2), float(collided), 1.0)
    if victims_found is not None:
        return dict(zip(SEARCH_TERMS, (*values, float(victims_found)), strict=True))
    return dict(zip(EXPLORE_TERMS, values, strict=True))


def auc_weight(step: int, max_steps: int) -> float:
    """The weight of step ``step``'s coverage gain in the coverage AUC (1-based ``step``).

    The evaluation's coverage AUC is the mean of the coverage after steps ``0..max_steps``
    (held at its last value after an early end), so a gain at step ``t`` counts in the
    ``max_steps + 1 - t`` means from ``t`` on.
    """
    return (max_steps + 1 - step) / (max_steps + 1)


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
