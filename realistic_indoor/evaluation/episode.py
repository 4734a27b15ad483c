"""One episode of an agent in an environment, and the metrics it yields."""

from __future__ import annotations

import math
import time
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np

from realistic_indoor.evaluation.tasks import EpisodeTask, make_env

__all__ = ["SCALARS", "TEAM_SCALARS", "EpisodeResult", "play_episode", "run_episode"]

SCALARS = (
    "steps",
    "max_steps",
    "final_coverage",
    "coverage_auc",
    "reached_target",
    "time_to_target_s",
    "path_to_target_m",
    "path_length_m",
    "collisions",
    "episode_return",
    "victims_total",
    "victims_found",
    "time_to_first_victim_s",
    "time_to_all_victims_s",
    "agent_ms_per_step",
    "decisions",
)
"""The per-episode numbers (``NaN`` where they do not apply), in the order outputs list them."""
TEAM_SCALARS = (
    "overlap",
    "messages",
    "linked_to_base_share",
    "victims_reported",
    "doorways_reached",
    "crossings_reached",
    "rescue_score",
)
"""A team's own per-episode numbers (0 or ``NaN`` for a robot alone), listed after :data:`SCALARS`."""


@dataclass
class EpisodeResult:
    """What one episode measured.

    Attributes:
        agent: Agent name.
        env: Environment label (the id, or ``id:plan``).
        group: Environment group (the id, ``id:plan-stem`` for one plan file, or ``id:folder``).
        seed: The episode's seed.
        steps: Control steps taken.
        max_steps: The environment's step limit.
        dt_s: Duration of a control step (s).
        final_coverage: Share of the reachable floor observed at the end.
        coverage_auc: Mean coverage over the whole step limit, an episode that ended early
            held at its final coverage: the area under the coverage-time curve, in ``[0, 1]``.
            It rewards exploring fast, and still ranks agents that all reach the target.
        reached_target: 1 if the coverage reached the task's target (0.9), else 0.
        time_to_target_s: Time at which it did (s); ``NaN`` if it did not.
        path_to_target_m: Distance driven until then (m); ``NaN`` if it did not.
        path_length_m: Distance driven in the episode (m).
        collisions: Steps with a wall contact.
        episode_return: Sum of the rewards.
        victims_total: Victims in the building (0 in exploration).
        victims_found: Victims found.
        time_to_first_victim_s: Time the first victim was found (s); ``NaN`` if none was.
        time_to_all_victims_s: Time the last one was (s); ``NaN`` unless all were.
        victim_times_s: Time each found victim was found, in order (s).
        agent_ms_per_step: The agent's thinking time per step (ms, wall clock).
        decisions: Goals the agent chose (the map-based and learned explorers' plans; 0 for
            agents that choose none), so that ``agent_ms_per_step * steps / decisions`` is the
            time per decision. A team's: every robot's.
        robots: Robots in the team (1 for a robot alone). In a team's episode the coverage,
            the time to the target and the victims are the team's (what all its robots
            observed), ``path_length_m`` and ``collisions`` the sums over its robots.
        overlap: Share of the floor the team's robots saw with their own lasers that two or
            more of them saw (:class:`~realistic_indoor.evaluation.overlap.ViewOverlap`; 0 alone).
        messages: Messages the team's robots sent over their links (team total; 0 alone).
        linked_to_base_share: Share of robot-steps a robot was connected to the base station,
            directly or through others (``NaN`` for a robot alone).
        victims_reported: Findings that reached the base station through the links (0 alone).
        doorways_reached: Share of the building's inside doorways into rooms a robot came
            within 1 m of (:mod:`~realistic_indoor.evaluation.rescue_score`; ``NaN`` alone or
            without doorways).
        crossings_reached: Share of the openings between corridors and halls a robot came
            within 1 m of (``NaN`` alone or without any).
        rescue_score: The RoboCup Rescue Virtual Robot League style score of the team's run
            (:func:`~realistic_indoor.evaluation.rescue_score.rescue_score`; ``NaN`` alone).
        coverage_t: Coverage every ``curve_every_steps`` steps, from the start.
        curve_dt_s: Time between entries of ``coverage_t`` (s).
        coverage_d: Coverage every ``curve_every_m`` metres driven, from the start.
        curve_dd_m: Distance between entries of ``coverage_d`` (m).
    """

    agent: str
    env: str
    group: str
    seed: int
    steps: int
    max_steps: int
    dt_s: float
    final_coverage: float
    coverage_auc: float
    reached_target: int
    time_to_target_s: float
    path_to_target_m: float
    path_length_m: float
    collisions: int
    episode_return: float
    victims_total: int
    victims_found: int
    time_to_first_victim_s: float
    time_to_all_victims_s: float
    victim_times_s: list[float] = field(default_factory=list)
    agent_ms_per_step: float = math.nan
    decisions: int = 0
    robots: int = 1
    overlap: float = math.nan
    messages: int = 0
    linked_to_base_share: float = math.nan
    victims_reported: int = 0
    doorways_reached: float = math.nan
    crossings_reached: float = math.nan
    rescue_score: float = math.nan
    coverage_t: list[float] = field(default_factory=list)
    curve_dt_s: float = 0.0
    coverage_d: list[float] = field(default_factory=list)
    curve_dd_m: float = 0.0

    def to_dict(self) -> dict[str, Any]:
        """The result as plain JSON-ready values."""
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> EpisodeResult:
        """The inverse of :meth:`to_dict`."""
        return cls(**data)


def run_episode(task: EpisodeTask) -> EpisodeResult:
    """Run one episode and measure it.

    The agent is built for the environment's robot (:func:`~realistic_indoor.agents.make_agent`)
    and sees only observations and ``info``; the metrics come from ``info`` after each step.

    Raises:
        ConfigError: For an unknown agent or a bad environment argument.
        PlanFormatError: If the environment's plan cannot be read.
    """
    from realistic_indoor.agents import agent_observations, make_agent

    env = make_env(task.env, agent_observations(task.agent))
    try:
        return play_episode(env, make_agent(task.agent, env), task)
    finally:
        env.close()


def play_episode(env: Any, agent: Any, task: EpisodeTask) -> EpisodeResult:
    """Run ``agent`` for one episode of ``env`` (seeded with ``task.seed``) and measure it.

    For an agent built by hand (not by name); ``task.agent`` is only its label in the result.
    """
    obs, info = env.reset(seed=task.seed)
    agent.reset(seed=task.seed)
    log = _Log(info)
    thinking = 0.0
    done = False
    while not done:
        t0 = time.perf_counter()
        action = agent.act(obs, info)
        thinking += time.perf_counter() - t0
        obs, reward, terminated, truncated, info = env.step(action)
        log.add(info, float(reward))
        done = terminated or truncated
    config = env.unwrapped.config
    result = log.result(task, 1.0 / config.robot.control_hz, config.max_steps, thinking)
    result.decisions = _decisions(agent)
    return result


def _decisions(agent: Any) -> int:
    """Goals an agent chose in its episode: policy calls or plans (0 for an agent with neither)."""
    if hasattr(agent, "decisions"):
        return int(agent.decisions)
    navigator = getattr(agent, "navigator", None)
    return int(navigator.plans) if navigator is not None else 0


class _Log:
    """Per-step coverage, distance, victims and reward of an episode."""

    def __init__(self, info: dict[str, Any]) -> None:
        self.coverage = [float(info["coverage"])]
        self.path = [float(info["path_length_m"])]
        self.found = [int(info.get("victims_found", 0))]
        self.victims_total = int(info.get("victims_total", 0))
        self.collisions = 0
        self.reward = 0.0

    def add(self, info: dict[str, Any], reward: float) -> None:
        self.coverage.append(float(info["coverage"]))
        self.path.append(float(info["path_length_m"]))
        self.found.append(int(info.get("victims_found", 0)))
        self.collisions = int(info["collisions"])
        self.reward += reward

    def result(self, task: EpisodeTask, dt_s: float, max_steps: int, thinking_s: float) -> EpisodeResult:
        coverage = np.array(self.coverage)
        path = np.array(self.path)
        steps = len(coverage) - 1
        hit = np.flatnonzero(coverage >= task.target)
        victim_steps = _first_steps(np.array(self.found))
        times = [round(s * dt_s, 6) for s in victim_steps]
        nan = math.nan
        return EpisodeResult(
            agent=task.agent,
            env=task.env.label,
            group=task.env.group,
            seed=task.seed,
            steps=steps,
            max_steps=max_steps,
            dt_s=dt_s,
            final_coverage=float(coverage[-1]),
            coverage_auc=_auc(coverage, max_steps),
            reached_target=int(len(hit) > 0),
            time_to_target_s=float(hit[0] * dt_s) if len(hit) else nan,
            path_to_target_m=float(path[hit[0]]) if len(hit) else nan,
            path_length_m=float(path[-1]),
            collisions=self.collisions,
            episode_return=self.reward,
            victims_total=self.victims_total,
            victims_found=int(self.found[-1]),
            time_to_first_victim_s=times[0] if times else nan,
            time_to_all_victims_s=times[-1] if times and self.found[-1] == self.victims_total else nan,
            victim_times_s=times,
            agent_ms_per_step=1000.0 * thinking_s / max(steps, 1),
            coverage_t=[round(float(c), 5) for c in coverage[:: task.curve_every_steps]],
            curve_dt_s=task.curve_every_steps * dt_s,
            coverage_d=_by_distance(coverage, path, task.curve_every_m),
            curve_dd_m=task.curve_every_m,
        )


def _auc(coverage: np.ndarray, max_steps: int) -> float:
    """Mean coverage over steps 0..max_steps, held at the last value after the episode ended."""
    held = coverage[-1] * max(0, max_steps + 1 - len(coverage))
    return float((coverage[: max_steps + 1].sum() + held) / (max_steps + 1))


def _first_steps(found: np.ndarray) -> list[int]:
    """The step at which each victim was found (a victim counts at the step the count rose)."""
    rises = np.diff(found, prepend=found[0] if len(found) else 0)
    steps: list[int] = []
    for step in np.flatnonzero(rises > 0):
        steps += [int(step)] * int(rises[step])
    victims_at_start = int(found[0]) if len(found) else 0
    return [0] * victims_at_start + steps


def _by_distance(coverage: np.ndarray, path: np.ndarray, every_m: float) -> list[float]:
    """Coverage when the distance driven first reached 0, ``every_m``, 2 ``every_m``, ... m."""
    marks = np.arange(0.0, path[-1] + 1e-9, every_m)
    idx = np.searchsorted(path, marks, side="left")
    return [round(float(c), 5) for c in coverage[np.minimum(idx, len(coverage) - 1)]]
