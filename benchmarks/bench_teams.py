"""Benchmark of robot teams: a team step as a multiple of single-robot steps, and memory per robot.

In one process, on default offices (``OfficeExplore-v0``), random actions, CPU time
(``time.process_time``), blocks of 100 steps after 50 warm-up steps:

1. the yardstick, ``CartPole-v1`` (``gym.make``, random actions, the same loop);
2. teams of 1, 2, 4 and 8 robots (``teams.parallel_env``), with the default links and map
   sharing (``wss``, ``comm``) and with ``unlimited`` links and a ``shared`` map, each against
   the native vector environment with one robot (``gym.make_vec(..., num_envs=1)``: the
   single-robot step on the same compiled core), five blocks of each in turn.

Each team row gives the median step times, the median of the blocks' ratios of a team step to
``n`` single-robot steps (blocks in turn, so that a machine whose load swings compares like with
like; issue 33 asks at most 1.3 with 4 and 8 robots, default settings), and the batch's memory
per robot (world, maps).

Usage::

    .venv/bin/python benchmarks/bench_teams.py            # about 30 seconds
    .venv/bin/python benchmarks/bench_teams.py --quick    # one size, one setting
"""

from __future__ import annotations

import argparse
import statistics
import time

import gymnasium as gym
import numpy as np

import realistic_indoor.envs  # noqa: F401  (registers the ids)
from realistic_indoor import teams
from realistic_indoor.machine import describe_machine

ENV_ID = "OfficeExplore-v0"
BLOCKS, BLOCK_STEPS, WARM = 5, 100, 50
SETTINGS = (("wss", "comm"), ("unlimited", "shared"))


def _block_s(step) -> float:
    """The CPU time of one call of ``step``, over a block of :data:`BLOCK_STEPS` calls (s)."""
    start = time.process_time()
    for _ in range(BLOCK_STEPS):
        step()
    return (time.process_time() - start) / BLOCK_STEPS


def cartpole_step_s() -> float:
    """CartPole-v1's step time with random actions (s), the yardstick: the median of the blocks."""
    env = gym.make("CartPole-v1")
    env.reset(seed=0)

    def step():
        _, _, terminated, truncated, _ = env.step(env.action_space.sample())
        if terminated or truncated:
            env.reset()

    return statistics.median(_block_s(step) for _ in range(BLOCKS))


def single_stepper(seed: int):
    """A step of the native vector environment with one robot: a single-robot step."""
    envs = gym.make_vec(ENV_ID, num_envs=1)
    envs.reset(seed=seed)
    rng = np.random.default_rng(seed)
    return lambda: envs.step(rng.uniform(-1, 1, (1, 2)).astype(np.float32))


def team_stepper(n: int, comm: str, sharing: str, seed: int):
    """A step of a team of ``n`` robots, and the team env."""
    env = teams.parallel_env(ENV_ID, n_robots=n, comm=comm, map_sharing=sharing)
    env.reset(seed=seed)
    rng = np.random.default_rng(seed)

    def step():
        env.step({a: rng.uniform(-1, 1, 2).astype(np.float32) for a in env.agents})
        if not env.agents:
            env.reset()

    return step, env


def compare(n: int, comm: str, sharing: str, seed: int) -> tuple[float, float, float, float]:
    """A team's step against a single robot's, block by block in turn (load swings hit both).

    Returns:
        Median team step (s), median single step (s), the median of the blocks' ratios of a team
        step to ``n`` single steps, and the batch's memory per robot (MB).
    """
    single = single_stepper(seed)
    team, env = team_stepper(n, comm, sharing, seed)
    for _ in range(WARM):
        single()
        team()
    pairs = [(_block_s(team), _block_s(single)) for _ in range(BLOCKS)]
    ratio = statistics.median(t / (n * s) for t, s in pairs)
    mb = env.simulation.batch.nbytes / n / 1e6
    return statistics.median(t for t, _ in pairs), statistics.median(s for _, s in pairs), ratio, mb


def main(argv: list[str] | None = None) -> None:
    """Print the benchmark's table."""
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--quick", action="store_true", help="teams of 4 with the default settings only")
    p.add_argument("--seed", type=int, default=0)
    args = p.parse_args(argv)
    print(f"# Robot teams ({ENV_ID}, CPU time, median of {BLOCKS} blocks of {BLOCK_STEPS} steps)\n")
    print(f"Machine: {describe_machine()}\n")
    cartpole = cartpole_step_s()
    print(f"CartPole-v1: {1 / cartpole:,.0f} steps/s.\n")
    print("| robots | comm | map_sharing | us a team step | us a single-robot step | x n single-robot steps "
          "| MB per robot |")  # fmt: skip
    print("|---:|---|---|---:|---:|---:|---:|")
    sizes, settings = ((4,), SETTINGS[:1]) if args.quick else ((1, 2, 4, 8), SETTINGS)
    for comm, sharing in settings:
        for n in sizes:
            team, single, ratio, mb = compare(n, comm, sharing, args.seed)
            print(
                f"| {n} | {comm} | {sharing} | {team * 1e6:.0f} | {single * 1e6:.0f} | {ratio:.2f} | {mb:.1f} |"
            )


if __name__ == "__main__":
    main()
