"""The learned explorer's policy: one small network scores every candidate goal alike.

Imported only where a learned model is trained or loaded (it needs torch and sb3-contrib).

The macro environments' ``candidates`` observation is K rows of the same features, one per
candidate goal. A plain MLP over the flattened rows would have to learn the same rule K times,
once per slot; here one MLP maps each row (with the share of the step limit left) to a score,
and the action's logits are the K scores. The critic reads the flattened observation.

With ``context`` each row also gets three figures of the whole decision, the same for every
candidate: the share of the candidates on offer that lie in rooms, their number (a share of K)
and their mean path cost. A score can then depend on the kind of place the robot is in (a
house's decisions mostly offer room frontiers only, a few metres away; an office's and a
school's offer corridor frontiers too, farther apart), which a row alone does not say.

With ``pool`` (a width W) each row also gets a learned summary of the whole decision: a second
small MLP embeds every offered row in W figures, and their mean and their maximum over the
offered candidates (2 W figures, the same for every row) join each row's input, as in Deep Sets
(Zaheer et al., NeurIPS 2017). The summary does not depend on the candidates' order, and a
candidate that is not offered changes nothing. It lets one network follow two rules where the
three fixed figures cannot tell them apart.
"""

from __future__ import annotations

from typing import Any

import torch
from sb3_contrib.common.maskable.policies import MaskableMultiInputActorCriticPolicy
from torch import nn

from realistic_indoor.envs.macro import CANDIDATE_FEATURES

__all__ = ["CONTEXT_FEATURES", "OBS_KEYS", "CandidatePolicy", "CandidateScorer", "decision_context"]

OBS_KEYS = ("candidates", "time_left")
"""The observation keys the policy reads (in this order: stable-baselines3 concatenates the keys
of a ``Dict`` observation in its sorted order, which is this one)."""

CONTEXT_FEATURES = ("room_share", "offered_share", "mean_path_cost")
"""The decision's figures a scorer with ``context`` adds to every row: the share of the offered
candidates in rooms, the offered candidates as a share of K, and their mean path cost (the
``path_cost`` feature's unit, 10 m)."""


class CandidateScorer(nn.Module):
    """Scores each candidate with one shared MLP: ``(B, K * F + 1) -> (B, K)`` logits.

    Args:
        n_candidates: K.
        hidden: Widths of the hidden layers.
        context: Give every row the decision's :data:`CONTEXT_FEATURES` too.
        pool: Width W of the learned summary of the decision given to every row (its mean and
            maximum over the offered candidates, 2 W figures); 0: none.
    """

    def __init__(
        self, n_candidates: int, hidden: tuple[int, ...] = (64, 64), context: bool = False, pool: int = 0
    ) -> None:
        super().__init__()
        self.k = n_candidates
        self.f = len(CANDIDATE_FEATURES)
        self.context = context
        self.pool = pool
        if pool:
            self.embed = nn.Sequential(nn.Linear(self.f + 1, 32), nn.Tanh(), nn.Linear(32, pool), nn.Tanh())
        layers: list[nn.Module] = []
        width = self.f + 1 + (len(CONTEXT_FEATURES) if context else 0) + 2 * pool
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
        parts = [rows, left]
        if self.context:
            parts.append(decision_context(rows).unsqueeze(1).expand(-1, self.k, len(CONTEXT_FEATURES)))
        if self.pool:
            parts.append(
                self._summary(torch.cat([rows, left], dim=-1)).unsqueeze(1).expand(-1, self.k, 2 * self.pool)
            )
        return self.head(self.body(torch.cat(parts, dim=-1))).squeeze(-1)

    def _summary(self, rows: torch.Tensor) -> torch.Tensor:
        """Mean and maximum of the offered rows' embeddings: ``(B, K, F + 1) -> (B, 2 W)`` (zeros if none)."""
        offered = (rows[..., CANDIDATE_FEATURES.index("valid")] > 0.5).unsqueeze(-1)
        e = self.embed(rows)
        count = offered.sum(1).clamp(min=1)
        mean = torch.where(offered, e, torch.zeros_like(e)).sum(1) / count
        top = e.masked_fill(~offered, float("-inf")).max(1).values
        top = torch.where(offered.any(1), top, torch.zeros_like(top))
        return torch.cat([mean, top], dim=-1)


def decision_context(rows: torch.Tensor) -> torch.Tensor:
    """The :data:`CONTEXT_FEATURES` of each decision: ``(B, K, F) -> (B, 3)``."""
    valid = (rows[..., CANDIDATE_FEATURES.index("valid")] > 0.5).float()
    offered = valid.sum(-1)
    per = offered.clamp(min=1.0)
    in_room = (rows[..., CANDIDATE_FEATURES.index("in_room")] > 0.5).float()
    cost = rows[..., CANDIDATE_FEATURES.index("path_cost")]
    return torch.stack(
        [(in_room * valid).sum(-1) / per, offered / rows.shape[1], (cost * valid).sum(-1) / per], dim=-1
    )


class CandidatePolicy(MaskableMultiInputActorCriticPolicy):
    """``MaskablePPO``'s ``MultiInputPolicy`` with :class:`CandidateScorer` as its action head.

    The observation must hold exactly :data:`OBS_KEYS`. The actor's MLP is empty (the scorer reads
    the observation itself); the critic's is ``net_arch["vf"]`` (64, 64 by default). ``context``
    (a ``policy_kwargs`` entry, saved with the model) gives the scorer the decision's
    :data:`CONTEXT_FEATURES`, and ``pool`` (another, saved alike) its learned summary of the
    decision (2 W figures: the mean and maximum of a W-wide embedding); models saved before
    either option load without it.
    """

    def __init__(
        self,
        observation_space: Any,
        action_space: Any,
        lr_schedule: Any,
        context: bool = False,
        pool: int = 0,
        **kwargs: Any,
    ) -> None:
        self.context = context
        self.pool = pool
        keys = tuple(observation_space.spaces)
        if keys != OBS_KEYS:
            raise ValueError(f"CandidatePolicy reads the observation keys {OBS_KEYS}, got {keys}")
        arch = kwargs.get("net_arch")
        # a dict when a saved policy is rebuilt from its own constructor parameters
        vf = arch["vf"] if isinstance(arch, dict) else list(arch or [64, 64])
        kwargs["net_arch"] = {"pi": [], "vf": list(vf)}
        super().__init__(observation_space, action_space, lr_schedule, **kwargs)

    def _build(self, lr_schedule: Any) -> None:
        super()._build(lr_schedule)
        self.action_net = CandidateScorer(int(self.action_space.n), context=self.context, pool=self.pool)
        self.optimizer = self.optimizer_class(self.parameters(), lr=lr_schedule(1), **self.optimizer_kwargs)

    def _get_constructor_parameters(self) -> dict[str, Any]:
        return {**super()._get_constructor_parameters(), "context": self.context, "pool": self.pool}
