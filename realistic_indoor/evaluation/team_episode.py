"""One episode of a team agent in a team environment, measured as the team's."""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from realistic_indoor.evaluation.episode import EpisodeResult, _Log
from realistic_indoor.evaluation.overlap import ViewOverlap
from realistic_indoor.evaluation.rescue_score import (
    CheckpointTracker,
    RescueScoreConfig,
    checkpoints,
    rescue_score,
)
from realistic_indoor.evaluation.tasks import EpisodeTask, make_team_env

__all__ = ["run_team_episode", "team_info"]


def team_info(infos: dict[str, dict[str, Any]]) -> dict[str, Any]:
    """The team's step, as a single robot's ``info``: the team's coverage and victims, sums of the rest.

    Args:
        infos: The team environment's infos, keyed by agent (every robot's, the team's
            coverage, victims and messages in each).
    """
    robots = list(infos.values())
    out = dict(robots[0])
    out["path_length_m"] = float(sum(i["path_length_m"] for i in robots))
    out["collisions"] = int(sum(i["collisions"] for i in robots))
    return out


def run_team_episode(task: EpisodeTask) -> EpisodeResult:
    """Run one episode of a team of ``task.robots`` and measure it as the team's.

    The team agent (:func:`~realistic_indoor.agents.team.make_team_agent`) sees only the
    robots' observations and infos; the metrics come from the infos after each step, summed
    over the robots where each has its own (distance, collisions, reward), and the rescue score
    from the robots' true poses (:mod:`~realistic_indoor.evaluation.rescue_score`).

    Raises:
        ConfigError: For an unknown team agent or a bad environment argument.
        PlanFormatError: If the environment's plan cannot be read.
    """
    from realistic_indoor.agents.team import make_team_agent

    env = make_team_env(task.env, task.robots)
    try:
        agent = make_team_agent(task.agent, env)
        observations, infos = env.reset(seed=task.seed)
        agent.reset(seed=task.seed)
        log = _Log(team_info(infos))
        views = _views(env, task.robots)
        score = RescueScoreConfig()
        reached = CheckpointTracker(checkpoints(env.simulation.world.building), score.reach_m)
        reached.add(env.simulation.poses)
        thinking, linked = 0.0, []
        while env.agents:
            t0 = time.perf_counter()
            actions = agent.act(observations, infos)
            thinking += time.perf_counter() - t0
            observations, rewards, _, _, infos = env.step(actions)
            log.add(team_info(infos), float(sum(rewards.values())))
            linked.append(np.mean([i["linked_to_base"] for i in infos.values()]))
            reached.add(env.simulation.poses)
            if views is not None:
                views.add(env.simulation.poses, env.simulation.out.scan)
        config = env.config
    finally:
        env.close()
    result = log.result(task, 1.0 / config.robot.control_hz, config.max_steps, thinking)
    last = next(iter(infos.values()))
    result.decisions = agent.plans
    result.robots = task.robots
    result.messages = int(last["messages"])
    result.linked_to_base_share = float(np.mean(linked)) if linked else float("nan")
    result.victims_reported = int(last.get("victims_reported", 0))
    result.overlap = 0.0 if views is None else views.share()
    result.doorways_reached = reached.doorways_share
    result.crossings_reached = reached.crossings_share
    result.rescue_score = rescue_score(result.victims_reported, reached.share, config=score)
    return result


def _views(env: Any, robots: int) -> ViewOverlap | None:
    """What each robot's laser sees, from its first scan on (``None`` for a robot alone: no overlap)."""
    if robots == 1:
        return None
    views = ViewOverlap(robots, env.config.lidar)
    views.add(env.simulation.poses, env.simulation.out.scan)
    return views
