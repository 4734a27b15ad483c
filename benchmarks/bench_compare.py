"""Side by side with another checkout: env step rates against CartPole-v1, and a new office's reset.

Runs the same three measurements with this checkout and with ``OTHER`` (a folder holding another
commit of the repository, e.g. made with ``git worktree add /tmp/old e06a6f2``), alternately,
each in a fresh process with that checkout first on ``PYTHONPATH``:

1. ``gym.make("OfficeExplore-v0")`` with random actions and ``CartPole-v1`` with random actions,
   the same loop, CPU time, the median of five blocks: steps/s and their ratio;
2. a new default office: ``make_generator("office")(rng)`` and ``World(building)``, CPU time, the
   median of 12 seeds (ms);
3. ``gym.make_vec("OfficeExplore-v0", num_envs=N)`` (``--num-envs``, 8 unless given) with random
   actions, CPU time, the median of three blocks of 300 steps: robot-steps per CPU second and
   their ratio to CartPole-v1 (whatever vector environment that checkout's ``make_vec`` gives:
   the native one, or Gymnasium's before it). CPU time sums the threads, so with ``--threads 2``
   the figure is per core; ``--threads`` sets ``NUMBA_NUM_THREADS`` in both processes.

Usage::

    .venv/bin/python benchmarks/bench_compare.py /tmp/old            # about two minutes
    .venv/bin/python benchmarks/bench_compare.py /tmp/old --rounds 3 --num-envs 64 --threads 1
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

MEASURE = r"""
import json, statistics, sys, time
import gymnasium as gym, numpy as np
import realistic_indoor  # noqa: F401  (registers the ids)
from realistic_indoor.generator import make_generator
from realistic_indoor.sim.world import World

def rate(env, n, warm, blocks, robots=1):
    # steps (robot-steps for a vector env) per CPU second: the median of blocks of n random actions
    env.reset(seed=0)
    env.action_space.seed(0)
    actions = [env.action_space.sample() for _ in range(n)]
    single = not isinstance(env, gym.vector.VectorEnv)  # a vector env resets its own episodes

    def step(a):
        _, _, terminated, truncated, _ = env.step(a)
        if single and (terminated or truncated):
            env.reset()

    for a in actions[:warm]:
        step(a)
    out = []
    for _ in range(blocks):
        start = time.process_time()
        for a in actions:
            step(a)
        out.append(robots * n / (time.process_time() - start))
    env.close()
    return statistics.median(out)

gen = make_generator("office")
World(gen(np.random.default_rng(100)))
gen_ms, world_ms = [], []
for seed in range(12):
    start = time.process_time()
    building = gen(np.random.default_rng(seed))
    middle = time.process_time()
    World(building)
    gen_ms.append(1e3 * (middle - start))
    world_ms.append(1e3 * (time.process_time() - middle))
cartpole = rate(gym.make("CartPole-v1"), 50_000, 200, 5)
office = rate(gym.make("OfficeExplore-v0"), 4_000, 200, 5)
n_envs = int(sys.argv[1])
vector = rate(gym.make_vec("OfficeExplore-v0", num_envs=n_envs), 300, 30, 3, robots=n_envs)
print(json.dumps({"cartpole": cartpole, "office": office, "vector": vector,
                  "generation_ms": statistics.median(gen_ms), "world_ms": statistics.median(world_ms)}))
"""


def measure(
    checkout: Path, num_envs: int = 8, threads: int | None = None, cache: Path | None = None
) -> dict[str, float]:
    """The figures of one checkout, measured in a fresh process.

    Args:
        checkout: Folder of the checkout, first on the process's ``PYTHONPATH``.
        num_envs: Sub-environments of the vector environment measured.
        threads: ``NUMBA_NUM_THREADS`` of the process; numba's default when ``None``.
        cache: ``NUMBA_CACHE_DIR`` of the process; the checkout's ``__pycache__`` when ``None``.

    Returns:
        Steps/s of the single env, the vector env and CartPole-v1, and the new office's
        generation and world build (ms), by name.
    """
    env = dict(os.environ, PYTHONPATH=str(checkout))
    if cache is not None:
        env["NUMBA_CACHE_DIR"] = str(cache)
    if threads is not None:
        env["NUMBA_NUM_THREADS"] = str(threads)
    done = subprocess.run(
        [sys.executable, "-c", MEASURE, str(num_envs)],
        env=env,
        cwd=checkout,
        capture_output=True,
        text=True,
        check=True,
    )
    return json.loads(done.stdout.strip().splitlines()[-1])


def main(argv: list[str] | None = None) -> None:
    """Print a Markdown table of both checkouts' figures, round after round."""
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("other", type=Path, help="folder of the other checkout")
    p.add_argument("--rounds", type=int, default=2, help="measurements of each checkout (default 2)")
    p.add_argument("--num-envs", type=int, default=8, help="sub-environments of the vector env (default 8)")
    p.add_argument("--threads", type=int, default=None, help="NUMBA_NUM_THREADS of both processes")
    args = p.parse_args(argv)
    if args.rounds < 1:
        p.error(f"--rounds must be at least 1, got {args.rounds}")
    if args.num_envs < 1:
        p.error(f"--num-envs must be at least 1, got {args.num_envs}")
    if args.threads is not None and not 1 <= args.threads <= (os.cpu_count() or 1):
        p.error(f"--threads must be between 1 and this machine's {os.cpu_count()} cores, got {args.threads}")
    here = Path(__file__).resolve().parents[1]
    if not (args.other / "realistic_indoor").is_dir():
        p.error(f"{args.other} holds no realistic_indoor package; give a checkout of this repository")
    print("| checkout | round | OfficeExplore-v0 steps/s | CartPole-v1 steps/s | x CartPole-v1 |"
          f" make_vec N = {args.num_envs} robot-steps per CPU s | x CartPole-v1 |"
          " generation ms | world build ms | generation + world ms |")  # fmt: skip
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as caches:
        _rounds(args, here, Path(caches))


def _rounds(args: argparse.Namespace, here: Path, caches: Path) -> None:
    """The table's rows: each checkout compiles into its own cache, made empty for this run.

    numba checks a cached kernel against its own module's file only, so a checkout's
    ``__pycache__`` may hold a kernel compiled with an older version of a kernel it calls.
    """
    for r in range(args.rounds):
        for name, checkout in (("other", args.other.resolve()), ("this", here)):
            m = measure(checkout, args.num_envs, args.threads, caches / name)
            total = m["generation_ms"] + m["world_ms"]
            print(
                f"| {name} ({checkout}) | {r + 1} | {m['office']:,.0f} | {m['cartpole']:,.0f} | "
                f"{m['office'] / m['cartpole']:.3f} | {m['vector']:,.0f} | {m['vector'] / m['cartpole']:.3f} | "
                f"{m['generation_ms']:.1f} | {m['world_ms']:.1f} | {total:.1f} |"
            )


if __name__ == "__main__":
    main()
