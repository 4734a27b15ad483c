"""Train a PPO explorer on a mix of building types, save it, and evaluate it against baselines.

A thin wrapper over ``realistic-indoor train`` (same options, same defaults; see
``realistic-indoor train --help``). Models go to a new ``runs/ppo_ENVS_PRESET.zip`` unless
``--out`` is given, so no default run touches the committed models in ``experiments/results/``.
To regenerate those (about 20 minutes each on 2 CPU cores)::

    .venv/bin/python experiments/train_ppo.py --envs realistic --out experiments/results/ppo_realistic.zip --overwrite
    .venv/bin/python experiments/train_ppo.py --envs random --out experiments/results/ppo_random.zip --overwrite

``--preset smoke`` checks the set-up in seconds; ``--no-train`` evaluates the model at ``--out``.
"""

from __future__ import annotations

import argparse
import sys


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    """The options of ``realistic-indoor train``."""
    from realistic_indoor.cli.train import add_arguments

    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_arguments(p)
    return p.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    """Train and evaluate as ``realistic-indoor train`` does; returns the exit code."""
    from realistic_indoor.cli.train import run

    return run(parse_args(argv))


if __name__ == "__main__":
    from realistic_indoor.cli import run_script

    sys.exit(run_script(main, "train_ppo.py"))
