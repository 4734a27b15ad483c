"""The evaluation after a training run: the trained PPO agent against baselines, paired seeds.

(It lives in ``evaluation/``, above ``agents/``, because it runs the evaluation runner.)
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from realistic_indoor.agents.rl.config import EvalPlan

__all__ = ["EVAL_METRICS", "evaluate_ppo", "format_evaluation"]

EVAL_METRICS = ("coverage_auc", "final_coverage", "reached_target", "path_length_m", "collisions")
"""The columns of the printed table (means with 95% intervals)."""


def evaluate_ppo(
    model_path: str | Path,
    env_ids: Sequence[str],
    plan: EvalPlan,
    out_dir: str | Path | None = None,
    workers: int | None = None,
    progress: bool = True,
    kind: str = "ppo",
) -> list[Any]:
    """Run the trained model and ``plan.baselines`` on ``env_ids`` for ``plan.episodes`` seeds each.

    The environments are the registered ids with ``plan``'s step limit and floor areas where it
    sets them (else the ids' own: default-size buildings); every agent gets the same seeds, hence
    the same buildings and starts.

    Args:
        model_path: The saved model (``.zip``).
        env_ids: Registered ids to evaluate on.
        plan: Episodes, step limit, baselines and first seed.
        out_dir: Folder for ``episodes.csv``, ``summary.csv``, ``results.json`` and the coverage
            figures; ``None`` writes nothing.
        workers: Parallel processes (``None``: one per core).
        progress: Show a progress bar.
        kind: The agent that runs the model: ``"ppo"`` (a primitive-action policy) or
            ``"learned"`` (the learned explorer, choosing goals).

    Returns:
        The :class:`~realistic_indoor.evaluation.EpisodeResult` of every episode.

    Raises:
        ConfigError: If the model, an id or an argument is invalid (before any episode runs).
    """
    from realistic_indoor.evaluation import evaluate

    return evaluate(
        [f"{kind}:{model_path}", *plan.baselines],
        [_env_spec(env_id, plan) for env_id in env_ids],
        episodes=plan.episodes,
        seed=plan.seed,
        workers=workers,
        out_dir=out_dir,
        progress=progress,
    )


def _env_spec(env_id: str, plan: EvalPlan) -> Any:
    """The evaluation environment of ``env_id``: ``plan``'s step limit and floor area, if set."""
    from realistic_indoor.envs import PRESETS
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.evaluation import EnvSpec

    if env_id not in PRESETS:
        raise ConfigError(f"unknown environment id {env_id!r}; registered: {', '.join(PRESETS)}")
    kwargs: dict[str, Any] = {} if plan.max_steps is None else {"max_steps": plan.max_steps}
    building_type = PRESETS[env_id].building_type
    if plan.areas_m2 is not None and building_type in plan.areas_m2:
        kwargs["area_m2"] = plan.areas_m2[building_type]
    return EnvSpec(env_id, None, kwargs)


def format_evaluation(results: Sequence[Any]) -> str:
    """The summary table of :func:`evaluate_ppo`'s results (:data:`EVAL_METRICS` per agent and id)."""
    from realistic_indoor.evaluation import format_table, summarize

    return format_table(summarize(list(results)), EVAL_METRICS)
