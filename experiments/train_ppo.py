"""Train a PPO explorer on a mix of building types, save it, and evaluate it against baselines.

Default run (about 20 minutes on 2 CPU cores; 500k steps on offices, schools and houses)::

    .venv/bin/python experiments/train_ppo.py --out experiments/results/ppo_realistic.zip

Train on the random baseline instead, or a longer run for a better policy::

    .venv/bin/python experiments/train_ppo.py --envs random --out experiments/results/ppo_random.zip
    .venv/bin/python experiments/train_ppo.py --preset long --out experiments/results/ppo_long.zip

The model is saved with its config and training curve (``.json`` beside it); the evaluation
(the PPO agent, the random agent and the frontier explorer on the default-size environments)
goes to ``<out>_eval/`` and is printed. ``--no-train`` evaluates the model already at ``--out``.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from realistic_indoor.agents.rl.config import RANDOM_IDS, REALISTIC_IDS

ENV_SETS = {"realistic": REALISTIC_IDS, "random": RANDOM_IDS}
EVAL_METRICS = ("final_coverage", "reached_target", "path_length_m", "collisions")


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--preset", default="default", help="default (~20 min), long (hours) or smoke (seconds)")
    p.add_argument(
        "--envs", default="realistic", help="realistic, random, or comma-separated ids to train on"
    )
    p.add_argument("--out", default="experiments/results/ppo_realistic.zip", help="model file to write")
    p.add_argument("--timesteps", type=int, default=None, help="override the preset's training steps")
    p.add_argument("--seed", type=int, default=0, help="training seed")
    p.add_argument("--eval-envs", default=None, help="ids to evaluate on (default: the training ids)")
    p.add_argument(
        "--eval-episodes", type=int, default=10, help="episodes per agent and id (0: no evaluation)"
    )
    p.add_argument("--eval-max-steps", type=int, default=None, help="step limit of the evaluation episodes")
    p.add_argument("--workers", type=int, default=None, help="evaluation processes (default: cores)")
    p.add_argument("--no-train", action="store_true", help="only evaluate the model already at --out")
    return p.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    from realistic_indoor.agents.rl import ppo_preset, train_ppo
    from realistic_indoor.evaluation import evaluate, format_table, summarize

    args = parse_args(argv)
    env_ids = ENV_SETS.get(args.envs, tuple(e.strip() for e in args.envs.split(",") if e.strip()))
    changes = {"env_ids": tuple(env_ids), "seed": args.seed}
    if args.timesteps is not None:
        changes["total_timesteps"] = args.timesteps
    config = ppo_preset(args.preset, **changes)
    model_path = Path(args.out).with_suffix(".zip")
    if not args.no_train:
        steps = config.total_timesteps
        print(f"training PPO ({args.preset}) on {', '.join(config.env_ids)} for {steps} steps", flush=True)
        result = train_ppo(config, model_path, log=lambda line: print(line, flush=True))
        print(
            f"saved {result.model_path} after {result.seconds:.0f} s, {result.episodes} episodes", flush=True
        )
    if args.eval_episodes <= 0:
        return 0
    eval_ids = args.eval_envs.split(",") if args.eval_envs else list(config.env_ids)
    out_dir = Path(args.out).with_suffix("").as_posix() + "_eval"
    kwargs = {} if args.eval_max_steps is None else {"max_steps": args.eval_max_steps}
    results = evaluate(
        [f"ppo:{model_path}", "random", "frontier"],
        eval_ids,
        episodes=args.eval_episodes,
        seed=1000,
        workers=args.workers,
        out_dir=out_dir,
        env_kwargs=kwargs,
    )
    print(format_table(summarize(results), EVAL_METRICS))
    print(f"evaluation in {out_dir}/")
    return 0


if __name__ == "__main__":
    from realistic_indoor.cli import run_script

    sys.exit(run_script(main, "train_ppo.py"))
