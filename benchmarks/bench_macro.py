"""Benchmark of the frontier macro actions: decisions and primitive steps per second.

For one registered id with ``action_type="frontier"`` (default ``OfficeExplore-v0``, default
buildings and step limit), a policy that always chooses candidate 0 (which drives as the
nearest-frontier explorer) runs whole episodes; the table gives decisions per second, primitive
(control) steps per second, primitive steps per decision, and beside them the nearest-frontier
agent on primitive actions in the same buildings (its steps per second: the same robot and
navigator, driven step by step) and ``CartPole-v1`` (``gym.make``, random actions, the same loop)
as the yardstick, every rate also as a ratio to CartPole-v1's in the same run. Times are CPU
seconds of this process (``time.process_time``).

With ``--vector N,M``, a second table gives the decisions per second (wall clock) of Gymnasium's
vector environments of N and M copies, ``vectorization_mode="sync"`` (one after another) and
``"async"`` (one process each), all choosing candidate 0 and reading ``action_masks`` through
``call`` as a masked learner does, each copy making the same number of decisions, beside one
environment in the same loop: the native vector
environment runs primitive actions only, and these are what runs macro actions.

Usage::

    .venv/bin/python benchmarks/bench_macro.py                  # 3 episodes, about a minute
    .venv/bin/python benchmarks/bench_macro.py --episodes 5 --env SchoolExplore-v0
    .venv/bin/python benchmarks/bench_macro.py --episodes 1 --vector 2,4
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
    p.add_argument("--vector", help="also time sync and async vector envs of these sizes, e.g. 2,4")
    p.add_argument(
        "--decisions",
        type=int,
        default=80,
        help="decisions of each environment per vector timing (default 80)",
    )
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
    if args.vector:
        _vector_table(args.env, [int(n) for n in args.vector.split(",")], args.decisions)


def _vector_table(env_id: str, sizes: list[int], decisions: int) -> None:
    """Decisions per second (wall clock) of one env and of sync and async vector envs."""
    one = _decision_rate(
        lambda: gym.make_vec(env_id, num_envs=1, vectorization_mode="sync", action_type="frontier"), decisions
    )
    print("\n| environments | decisions/s (wall clock) | x one environment |")
    print("|---|---:|---:|")
    print(f"| one | {one:.1f} | 1.00 |")
    for n in sizes:
        for mode in ("sync", "async"):
            rate = _decision_rate(
                lambda n=n, mode=mode: gym.make_vec(
                    env_id, num_envs=n, vectorization_mode=mode, action_type="frontier"
                ),
                decisions,
            )
            print(f"| {n}, {mode} | {rate:.1f} | {rate / one:.2f} |")


def _decision_rate(make, decisions: int) -> float:
    """Decisions per wall-clock second of a vector env choosing candidate 0 (reset not timed).

    Every copy makes ``decisions`` decisions, so each is as far into its episode (a decision
    costs more as the robot's map grows) whatever the number of copies.
    """
    import numpy as np

    envs = make()
    envs.reset(seed=0)
    done = 0
    t0 = time.perf_counter()
    while done < decisions * envs.num_envs:  # each environment as far into its episode
        masks = np.stack(envs.call("action_masks"))
        envs.step(np.zeros(envs.num_envs, dtype=np.int64) * masks[:, 0])
        done += envs.num_envs
    rate = done / (time.perf_counter() - t0)
    envs.close()
    return rate


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
