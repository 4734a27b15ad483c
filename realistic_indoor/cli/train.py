"""``realistic-indoor train``: train a PPO explorer on a mix of building types, then evaluate it.

``experiments/train_ppo.py`` is a thin wrapper over this module (same options, same defaults).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from realistic_indoor.errors import ConfigError

RUNS_DIR = Path("runs")
"""Where models go by default (ignored by git)."""

_DESCRIPTION = (
    "Train a PPO explorer (stable-baselines3, MultiInputPolicy on the scan, local map and velocity) "
    "on a mix of building types, save it with its config and training curve (.json beside the "
    ".zip), then evaluate it against the random agent and the frontier explorer on the training "
    "ids at their default size. With --preset learned, train the learned explorer instead: a "
    "policy choosing among candidate goals (frontier macro actions, sb3-contrib MaskablePPO, "
    "cloned from a classical rule first, --teacher), evaluated against the frontier, utility "
    'and structure explorers. Needs the rl extra: pip install "realistic-indoor[rl]".'
)
_EPILOG = """\
presets (measured on 2 CPU cores):
  smoke    256 steps on small buildings, then 1 episode of 50 steps per agent and id:
           checks the set-up in 11 seconds (21-31 s on busy cores); the policy learns nothing
  default  500,000 steps (about 20 minutes), then 2 episodes per agent and id at the ids'
           step limits (140 CPU-seconds: 2 to 6 minutes)
  long     3,000,000 steps on bigger buildings (hours), then 10 episodes per agent and id
           (5 times the default's evaluation)
  global-map  the default, with the robot's whole map (global_map) and the share of the step
           limit left (time_left) in the policy's view; its environments run in sub-processes
  learned  the learned explorer on offices, schools and houses at their default sizes and
           step limits: 20,000 decisions cloning the structure-utility-area-short rule
           (the gain rule in houses; --teacher names one rule for every id), every id
           weighed alike, then 40,000 of MaskablePPO (--timesteps sets these; 22 to 39
           minutes), then 2 episodes per agent and id; the policy's scorer sees the decision's
           context and a learned summary of all its candidates
  learned-house-rule  the learned recipe before the scorer's summary and the balanced
           cloning: the same rules, a scorer that sees three figures of the decision
  learned-one-rule  the learned recipe before houses had their own rule: one rule in every
           id, a policy that scores each candidate alone
  learned-smoke  seconds, on houses: checks the learned explorer's set-up

output:
  By default each run writes a new model under ./runs/ (ppo_ENVS_PRESET.zip, then
  ppo_ENVS_PRESET_2.zip, ...; learned_ENVS_PRESET.zip for the learned presets), so no run
  replaces another. An existing file given with
  --out is refused unless --overwrite. The evaluation goes to MODEL_eval/ beside the model.
  All paths are checked before training starts.

examples:
  realistic-indoor train --preset smoke
  realistic-indoor train --preset learned
  realistic-indoor train --envs realistic
  realistic-indoor train --preset global-map
  realistic-indoor train --envs random --out runs/ppo_random.zip --eval-envs RandomExplore-v0,OfficeExplore-v0
  realistic-indoor train --no-train --out runs/ppo_realistic_default.zip --eval-episodes 10"""


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``train`` subcommand."""
    p = sub.add_parser(
        "train",
        help="train a PPO explorer (presets smoke, default, long, global-map) or the learned explorer, then evaluate it",
        description=_DESCRIPTION,
        epilog=_EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_arguments(p)
    p.set_defaults(func=run)


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The options of ``train`` (shared with ``experiments/train_ppo.py``)."""
    from realistic_indoor.agents.rl.config import PPO_PRESETS, VEC_ENVS
    from realistic_indoor.agents.rl.learned import LEARNED_PRESETS
    from realistic_indoor.agents.rl.teachers import DEFAULT_TEACHER, TEACHERS

    p.add_argument(
        "--preset",
        default="default",
        choices=[*PPO_PRESETS, *LEARNED_PRESETS],
        help="training budget and evaluation (default: default; see below)",
    )
    p.add_argument(
        "--envs",
        default="realistic",
        help="realistic (offices, schools, houses), random (the baseline maps), or comma-separated "
        "registered ids to train on (default realistic)",
    )
    p.add_argument(
        "--timesteps",
        type=int,
        help="training steps over all environments (default: the preset's); for the learned "
        "presets, MaskablePPO's decisions after cloning",
    )
    p.add_argument("--seed", type=int, default=0, help="seed of the policy and the environments (default 0)")
    p.add_argument(
        "--vec-env",
        choices=VEC_ENVS,
        help="how the training environments run: batched (the ids' native vector environments, "
        "one compiled step each, in this process), subproc (a process each) or dummy (in turn, in "
        "this process); default: the preset's",
    )
    p.add_argument("--n-envs", type=int, help="environments trained on in parallel (default: the preset's)")
    p.add_argument(
        "--teacher",
        choices=TEACHERS,
        help="the learned presets only: the classical rule cloned before MaskablePPO, in every id (default: "
        f"the preset's: {DEFAULT_TEACHER}, and for the learned and learned-house-rule presets the gain rule "
        "in houses)",
    )
    p.add_argument(
        "--out",
        help="model file to write (.zip; its .json goes beside it); default: a new runs/ppo_ENVS_PRESET.zip",
    )
    p.add_argument("--overwrite", action="store_true", help="replace the model at --out if it exists")
    p.add_argument(
        "--eval-episodes",
        type=int,
        help="episodes per agent and id after training; 0 skips the evaluation (default: the preset's)",
    )
    p.add_argument(
        "--eval-max-steps",
        type=int,
        help="step limit of the evaluation episodes (default: the preset's; the ids' own for default, long)",
    )
    p.add_argument("--eval-envs", help="comma-separated ids to evaluate on (default: the training ids)")
    p.add_argument("--eval-out", help="folder of the evaluation (default: MODEL_eval/ beside the model)")
    p.add_argument("--workers", type=int, help="evaluation processes (default: one per CPU core)")
    p.add_argument(
        "--no-train",
        action="store_true",
        help="only evaluate the model already at --out (replacing its evaluation)",
    )
    p.add_argument("--quiet", action="store_true", help="no progress bars or progress lines")


def run(args: argparse.Namespace) -> int:
    """Check every path and option, train (unless ``--no-train``), save, then evaluate."""
    from realistic_indoor.agents.rl.config import env_ids_of

    _check_numbers(args)
    learned = _is_learned(args.preset)
    env_ids = env_ids_of(args.envs)
    config = _learned_config(args, env_ids) if learned else _config(args, env_ids)
    plan = _eval_plan(args)
    eval_ids = env_ids_of(args.eval_envs, "--eval-envs") if args.eval_envs is not None else config.env_ids
    model_path = _model_path(args, env_ids)
    eval_dir = _eval_dir(args, model_path) if plan.episodes else None
    if not args.no_train:
        (_train_learned if learned else _train)(args, config, model_path)
    if eval_dir is None:
        print("no evaluation (--eval-episodes 0)")
        return 0
    _evaluate(args, model_path, eval_ids, plan, eval_dir, "learned" if learned else "ppo")
    return 0


def _is_learned(preset: str) -> bool:
    from realistic_indoor.agents.rl.learned import LEARNED_PRESETS

    return preset in LEARNED_PRESETS


def _learned_config(args: argparse.Namespace, env_ids: tuple[str, ...]):
    from realistic_indoor.agents.rl.learned import LEARNED_PRESETS, learned_preset

    if args.vec_env is not None:
        raise ConfigError(
            "--vec-env is not used by the learned presets (they run sub-processes); leave it out"
        )
    changes: dict = {"seed": args.seed}
    if args.envs != "realistic" or "env_ids" not in LEARNED_PRESETS[args.preset]:
        changes["env_ids"] = env_ids
    if args.timesteps is not None:
        changes["ppo_decisions"] = args.timesteps
    if args.n_envs is not None:
        changes["n_envs"] = args.n_envs
    if args.teacher is not None:
        if args.no_train:
            raise ConfigError(
                "--teacher chooses the rule a training clones; with --no-train nothing is trained, leave it out"
            )
        changes["teacher"] = args.teacher
        changes["teacher_by_id"] = ()  # the rule asked for, in every id
    return learned_preset(args.preset, **changes)


def _check_numbers(args: argparse.Namespace) -> None:
    """Refuse counts out of range, naming the option."""
    for option, value, minimum in (
        ("--timesteps", args.timesteps, 1),
        ("--n-envs", args.n_envs, 1),
        ("--seed", args.seed, 0),
        ("--eval-episodes", args.eval_episodes, 0),
        ("--eval-max-steps", args.eval_max_steps, 1),
        ("--workers", args.workers, 1),
    ):
        if value is not None and value < minimum:
            raise ConfigError(f"{option} must be an integer >= {minimum}, not {value}")


def _config(args: argparse.Namespace, env_ids: tuple[str, ...]):
    from realistic_indoor.agents.rl.config import ppo_preset

    if args.teacher is not None:
        raise ConfigError(
            f"--teacher is for the learned presets (a rule to clone), not {args.preset}; leave it out"
        )
    changes = {"env_ids": env_ids, "seed": args.seed}
    if args.timesteps is not None:
        changes["total_timesteps"] = args.timesteps
    if args.vec_env is not None:
        changes["vec_env"] = args.vec_env
    if args.n_envs is not None:
        changes["n_envs"] = args.n_envs
    return ppo_preset(args.preset, **changes)


def _eval_plan(args: argparse.Namespace):
    from realistic_indoor.agents.rl.config import PPO_EVAL_PRESETS

    plan = PPO_EVAL_PRESETS[args.preset]
    if args.eval_episodes is not None:
        plan = plan.replace(episodes=args.eval_episodes)
    if args.eval_max_steps is not None:
        plan = plan.replace(max_steps=args.eval_max_steps)
    return plan


def envs_label(envs: str, env_ids: tuple[str, ...]) -> str:
    """The ``ENVS`` part of default model names: the set's name, or the ids shortened.

    >>> envs_label("OfficeExplore-v0,HouseExplore-v0", ("OfficeExplore-v0", "HouseExplore-v0"))
    'officeexplore-houseexplore'
    """
    from realistic_indoor.agents.rl.config import ENV_SETS

    if envs in ENV_SETS:
        return envs
    return "-".join(i.removesuffix("-v0").lower() for i in env_ids)


def default_model_path(label: str, preset: str, folder: Path = RUNS_DIR, new: bool = True) -> Path:
    """``folder/ppo_LABEL_PRESET.zip``, or with ``new`` the first of ``_2``, ``_3``, ... not taken.

    The learned presets' models are ``learned_LABEL_PRESET.zip`` (``learned_realistic_learned.zip``).

    Args:
        label: The training environments' label (:func:`envs_label`).
        preset: The preset's name.
        folder: The runs folder.
        new: Skip names whose model or evaluation folder exists.
    """
    stem = f"{'learned' if _is_learned(preset) else 'ppo'}_{label}_{preset}"
    path, n = folder / f"{stem}.zip", 1
    while new and (path.exists() or path.with_suffix(".json").exists() or _eval_dir_of(path).exists()):
        n += 1
        path = folder / f"{stem}_{n}.zip"
    return path


def _model_path(args: argparse.Namespace, env_ids: tuple[str, ...]) -> Path:
    """The model to write (or with ``--no-train`` to read), checked."""
    from realistic_indoor.files import check_output_path

    label = envs_label(args.envs, env_ids)
    if args.no_train:
        path = Path(args.out) if args.out else default_model_path(label, args.preset, new=False)
        if not path.is_file():
            raise ConfigError(f"--no-train evaluates the model at --out, and {path} is not a file")
        return path
    if args.out is None:
        path = default_model_path(label, args.preset)
        return check_output_path(path, "--out", (".zip",))
    path = check_output_path(args.out, "--out", (".zip",))
    if not args.overwrite:
        for taken in (path, path.with_suffix(".json")):
            if taken.exists():
                raise ConfigError(
                    f"--out {path}: {taken} exists; add --overwrite to replace it, or choose a new name"
                )
    return path


def _eval_dir_of(model_path: Path) -> Path:
    return model_path.with_name(f"{model_path.stem}_eval")


def _eval_dir(args: argparse.Namespace, model_path: Path) -> Path:
    """The evaluation folder, checked."""
    from realistic_indoor.files import check_output_dir

    folder = Path(args.eval_out) if args.eval_out else _eval_dir_of(model_path)
    return check_output_dir(folder, "--eval-out")


def _train(args: argparse.Namespace, config, model_path: Path) -> None:
    from realistic_indoor.agents.rl.train import require_rl, train_ppo

    require_rl()
    print(
        f"training PPO ({args.preset} preset, seed {config.seed}) on {', '.join(config.env_ids)} "
        f"for {config.total_timesteps:,} steps; model to {model_path}",
        flush=True,
    )
    log = (lambda line: None) if args.quiet else (lambda line: print(line, flush=True))
    result = train_ppo(config, model_path, log=log, progress=not args.quiet)
    print(
        f"saved {result.model_path} and {result.model_path.with_suffix('.json').name} after "
        f"{result.seconds:.0f} s of training, {result.episodes} episodes "
        f"(final coverage of the last 50: {result.last_coverage:.3f} on average)",
        flush=True,
    )


def _rules(config) -> str:
    """The cloned rules in words: ``structure rule (the gain rule in HouseExplore-v0)``."""
    other = [
        f"the {rule} rule in {env_id}" for env_id, rule in config.teacher_by_id if env_id in config.env_ids
    ]
    return f"{config.teacher} rule" + (f" ({'; '.join(other)})" if other else "")


def _scorer(config) -> str:
    """What the scorer sees and how cloning weighs the ids, in words."""
    sees = []
    if config.scorer_context:
        sees.append("the decision's context")
    if config.scorer_pool:
        sees.append(
            f"a pooled summary of the decision (the mean and maximum of {config.scorer_pool} learned figures)"
        )
    scorer = f"a scorer that sees {' and '.join(sees)}" if sees else "a scorer of each candidate alone"
    return scorer + (", every id weighed alike in cloning" if config.bc_balance else "")


def _train_learned(args: argparse.Namespace, config, model_path: Path) -> None:
    from realistic_indoor.agents.rl.learned import require_learned, train_learned

    require_learned()
    print(
        f"training the learned explorer ({args.preset} preset, seed {config.seed}) on {', '.join(config.env_ids)}: "
        f"{config.bc_decisions:,} decisions of cloning the {_rules(config)}, then {config.ppo_decisions:,} of "
        f"MaskablePPO; {_scorer(config)}; "
        f"model to {model_path}",
        flush=True,
    )
    log = (lambda line: None) if args.quiet else (lambda line: print(line, flush=True))
    train_learned(config, model_path, log=log)


def _evaluate(
    args: argparse.Namespace, model_path: Path, eval_ids, plan, eval_dir: Path, kind: str = "ppo"
) -> None:
    from realistic_indoor.evaluation.ppo import evaluate_ppo, format_evaluation

    agents = ", ".join((kind, *plan.baselines))
    print(
        f"evaluating {agents} on {plan.describe()} on {', '.join(eval_ids)} "
        "(--eval-episodes to change, 0 to skip)",
        flush=True,
    )
    results = evaluate_ppo(
        model_path, eval_ids, plan, eval_dir, workers=args.workers, progress=not args.quiet, kind=kind
    )
    print(format_evaluation(results))
    print(f"evaluation in {eval_dir}/")
