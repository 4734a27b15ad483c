"""The learned explorer's policy: one small network scores every candidate goal alike.

Imported only where a learned model is trained or loaded (it needs torch and sb3-contrib).

The macro environments' ``candidates`` observation is K rows of the same features, one per
candidate goal. A plain MLP over the flattened rows would have to learn the same rule K times,
once per slot; here one MLP maps each row (with the share of the step limit left) to a score,
and the action's logits are the K scores. The critic reads the flattened observation.
"""

from __future__ import annotations

from typing import Any

import torch
from sb3_contrib.common.maskable.policies import MaskableMultiInputActorCriticPolicy
from torch import nn

from realistic_indoor.envs.macro import CANDIDATE_FEATURES

__all__ = ["OBS_KEYS", "CandidatePolicy", "CandidateScorer"]

OBS_KEYS = ("candidates", "time_left")
"""The observation keys the policy reads (in this order: stable-baselines3 concatenates the keys
of a ``Dict`` observation in its sorted order, which is this one)."""


class CandidateScorer(nn.Module):
    """Scores each candidate with one shared MLP: ``(B, K * F + 1) -> (B, K)`` logits.

    Args:
        n_candidates: K.
        hidden: Widths of the hidden layers.
    """

    def __init__(self, n_candidates: int, hidden: tuple[int, ...] = (64, 64)) -> None:
        super().__init__()
        self.k = n_candidates
        self.f = len(CANDIDATE_FEATURES)
        layers: list[nn.Module] = []
        width = self.f + 1
        for h in hidden:
            layers += [nn.Linear(width, h), nn.Tanh()]
            width = h
        self.body = nn.Sequential(*layers)
        self.head = nn.Linear(width, 1)
        nn.init.orthogonal_(self.head.weight, gain=0.01)
        nn.init.zeros_(self.head.bias)

    def forward(self, latent: torch.Tensor) -> torch.Tensor:
        """The K logits of each row of ``latent`` (flat candidates, then time left)."""
        rows = latent[:, : self.k * self.f].reshape(-1, self.k, self.f)
        left = latent[:, self.k * self.f : self.k * self.f + 1].unsqueeze(1).expand(-1, self.k, 1)
        return self.head(self.body(torch.cat([rows, left], dim=-1))).squeeze(-1)


class CandidatePolicy(MaskableMultiInputActorCriticPolicy):
    """``MaskablePPO``'s ``MultiInputPolicy`` with :class:`CandidateScorer` as its action head.

    The observation must hold exactly :data:`OBS_KEYS`. The actor's MLP is empty (the scorer reads
    the observation itself); the critic's is ``net_arch["vf"]`` (64, 64 by default).
    """

    def __init__(self, observation_space: Any, action_space: Any, lr_schedule: Any, **kwargs: Any) -> None:
        keys = tuple(observation_space.spaces)
        if keys != OBS_KEYS:
            raise ValueError(f"CandidatePolicy reads the observation keys {OBS_KEYS}, got {keys}")
        kwargs["net_arch"] = {"pi": [], "vf": list(kwargs.get("net_arch") or [64, 64])}
        super().__init__(observation_space, action_space, lr_schedule, **kwargs)

    def _build(self, lr_schedule: Any) -> None:
        super()._build(lr_schedule)
        self.action_net = CandidateScorer(int(self.action_space.n))
        self.optimizer = self.optimizer_class(self.parameters(), lr=lr_schedule(1), **self.optimizer_kwargs)
