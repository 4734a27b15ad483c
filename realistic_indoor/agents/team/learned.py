"""The learned explorer per robot: each robot's goals chosen by the single-robot policy, uncoordinated.

Every robot runs the team explorers' navigator on the map its links give it (as ``frontier``
does) and, where it would replan, offers the policy of the learned explorer
(:class:`~realistic_indoor.agents.rl.learned_agent.LearnedAgent`) the same candidate goals, with
the same features, as the single-robot environment's ``"frontier"`` macro actions would: the K
nearest frontiers of the map it knows, ranked by path cost. The policy picks one; teammates play
no part in the choice (the policy was trained alone), so the team shares maps but not frontiers,
like uncoordinated ``frontier``. A detected victim in search is driven to at once, as by the
classical team explorers, without asking the policy.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from realistic_indoor.agents.rl.learned_agent import DEFAULT_MODEL, load_learned_model
from realistic_indoor.agents.team.base import TeamSpec
from realistic_indoor.agents.team.explorer import TeamExplorer, Teammate
from realistic_indoor.envs.macro import MacroConfig, candidate_features, rank_candidates
from realistic_indoor.envs.observations import time_left
from realistic_indoor.navigation.frontiers import Frontiers
from realistic_indoor.navigation.navigator import ExplorerConfig, Found, PlanContext, PlanOptions

__all__ = ["TeamLearnedAgent"]


class TeamLearnedAgent(TeamExplorer):
    """Each robot asks the learned explorer's policy which of its candidate goals to go to.

    With a policy that always answers 0 every robot goes to its nearest frontier: the team
    drives exactly as :class:`~realistic_indoor.agents.team.frontier.TeamFrontierAgent`.

    Args:
        spec: The team's datasheet.
        model: Path of a saved ``MaskablePPO`` model (``.zip``), or a loaded model (anything
            with ``action_space.n`` and ``predict(obs, action_masks=..., deterministic=...)``);
            default: the committed learned explorer.
        max_steps: The episode's step limit, for the policy's ``time_left`` (control steps);
            :func:`~realistic_indoor.agents.team.make_team_agent` reads it from the environment.
        deterministic: Take the most likely choice (else sample from the policy).
        config: Every robot's navigator settings.

    Attributes:
        decisions: Times the policy was asked this episode, all robots together.
    """

    name = "learned"

    def __init__(
        self,
        spec: TeamSpec,
        model: str | Path | Any | None = None,
        max_steps: int = 6000,
        deterministic: bool = True,
        config: ExplorerConfig | None = None,
    ) -> None:
        model = DEFAULT_MODEL if model is None else model
        self.model = load_learned_model(model) if isinstance(model, (str, Path)) else model
        self.source = str(model) if isinstance(model, (str, Path)) else type(model).__name__
        self.max_steps = int(max_steps)
        self.deterministic = deterministic
        self.macro_config = MacroConfig(n_candidates=int(self.model.action_space.n))
        super().__init__(spec, config)

    def reset(self, seed: int | None = None) -> None:
        """Forget the episode (maps, plans, the step count)."""
        super().reset(seed)
        self._steps = 0
        self.decisions = 0

    def act(
        self, observations: dict[str, dict[str, np.ndarray]], infos: dict[str, dict[str, Any]]
    ) -> dict[str, np.ndarray | int]:
        """Every robot's action; the policy is asked for each robot that replans this step."""
        actions = super().act(observations, infos)
        self._steps += 1
        return actions

    def _choose(
        self, robot: int, frontiers: Frontiers, ctx: PlanContext, teammates: list[Teammate]
    ) -> Found | None:
        navigator = self.navigators[robot]
        k = self.macro_config.n_candidates
        candidates = rank_candidates(PlanOptions(ctx, frontiers, None, None), self.macro_config, navigator)
        if candidates.count == 0:
            return None
        obs = {
            "candidates": candidate_features(candidates, navigator.pose, k),
            "time_left": time_left(self._steps, self.max_steps),
        }
        masks = np.arange(k) < candidates.count
        choice, _ = self.model.predict(obs, action_masks=masks, deterministic=self.deterministic)
        self.decisions += 1
        index = int(choice)
        return candidates.goals[index if 0 <= index < candidates.count else 0]

    def __repr__(self) -> str:
        return f"TeamLearnedAgent({self.source!r}, n_robots={self.spec.n_robots})"
