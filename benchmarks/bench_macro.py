"""Benchmark of the frontier macro actions: decisions and primitive steps per second.

For one registered id with ``action_type="frontier"`` (default ``OfficeExplore-v0``, default
buildings and step limit), a policy that always chooses candidate 0 (which drives as the
nearest-frontier explorer) runs whole episodes; the table gives decisions per second, primitive
(control) steps per second, primitive steps per decision, and beside them the nearest-frontier
agent on primitive actions in the same buildings (its steps per second: the same robot and
navigator, driven step by step) and ``CartPole-v1`` (``gym.make``, random actions, the same loop)
as the yardstick, every rate also as a ratio to CartPole-v1's in the same run. Times are CPU
seconds of this process (``time.process_time``).

Usage::

    .venv/bin/python benchmarks/bench_macro.py                  # 3 episodes, about a minute
    .venv/bin/python benchmarks/bench_macro.py --episodes 5 --env SchoolExplore-v0
"""

from __future__ import annotations

import argparse
import time

import gymnasium as gym
from bench_envs import machine

import realistic_indoor.envs  # noqa: F401  (registers the ids)
from realistic_indoor.agents import make_agent


def main(argv: list[str] | None = None) -> None:
    """Run the benchmark and print its table."""
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default="OfficeExplore-v0", help="registered id (default OfficeExplore-v0)")
    p.add_argument("--episodes", type=int, default=3, help="episodes, seeds 0.. (default 3)")
    args = p.parse_args(argv)
    cartpole = _cartpole_rate(20_000)
    decisions, steps, macro_s = 0, 0, 0.0
    agent_steps, agent_s = 0, 0.0
    for seed in range(args.episodes):
        d, n, t = _macro_episode(args.env, seed)
        decisions, steps, macro_s = decisions + d, steps + n, macro_s + t
        n, t = _frontier_episode(args.env, seed)
        agent_steps, agent_s = agent_steps + n, agent_s + t
    print(f"# Frontier macro actions on {args.env}, {args.episodes} episodes ({machine()})\n")
    print(f"CartPole-v1: {cartpole:,.0f} steps/s\n")
    print("| loop | decisions/s | primitive steps/s | x CartPole-v1 | steps per decision |")
    print("|---|---:|---:|---:|---:|")
    rate = steps / macro_s
    print(
        f"| macro, always candidate 0 | {decisions / macro_s:,.0f} | {rate:,.0f} | {rate / cartpole:.3f} "
        f"| {steps / decisions:.1f} |"
    )
    rate = agent_steps / agent_s
    print(f"| frontier agent, primitive actions | - | {rate:,.0f} | {rate / cartpole:.3f} | - |")


def _cartpole_rate(n_steps: int) -> float:
    env = gym.make("CartPole-v1")
    env.action_space.seed(0)
    env.reset(seed=0)
    t0 = time.process_time()
    for _ in range(n_steps):
        _, _, terminated, truncated, _ = env.step(env.action_space.sample())
        if terminated or truncated:
            env.reset()
    return n_steps / (time.process_time() - t0)


def _macro_episode(env_id: str, seed: int) -> tuple[int, int, float]:
    """Decisions, primitive steps and CPU seconds of one always-0 episode (reset not timed)."""
    env = gym.make(env_id, action_type="frontier")
    env.reset(seed=seed)
    decisions, done = 0, False
    t0 = time.process_time()
    while not done:
        _, _, terminated, truncated, info = env.step(0)
        decisions += 1
        done = terminated or truncated
    return decisions, info["steps"], time.process_time() - t0


def _frontier_episode(env_id: str, seed: int) -> tuple[int, float]:
    """Steps and CPU seconds of the nearest-frontier agent's episode (reset not timed)."""
    env = gym.make(env_id)
    agent = make_agent("frontier", env)
    obs, info = env.reset(seed=seed)
    agent.reset()
    steps, done = 0, False
    t0 = time.process_time()
    while not done:
        obs, _, terminated, truncated, info = env.step(agent.act(obs, info))
        steps += 1
        done = terminated or truncated
    return steps, time.process_time() - t0


if __name__ == "__main__":
    main()
