"""The learned explorer's training recipe: choose among candidate goals with sb3-contrib's ``MaskablePPO``.

The environments run with frontier macro actions (``action_type="frontier"``): the policy picks
one of K candidate goals where the classical explorers would choose a goal, and their navigator
drives there. The reward is the metric (``coverage_auc``, scaled by :attr:`LearnedConfig.reward_scale`):
an episode's return is its coverage AUC minus the coverage at reset. Training runs at the
evaluation's sizes and step limits (the generators' default areas, the ids' own limits).

The recipe, :func:`train_learned`:

1. **Behaviour cloning** from a classical explorer's rule, which the candidates' features
   express exactly (:attr:`LearnedConfig.teacher`, by default ``structure-utility-area-short``:
   three times the path cost, doubled for a frontier in a room and doubled for one shorter than
   1 m, less the frontier's length and twice the unobserved area near it; a detected victim
   first; :mod:`~realistic_indoor.agents.rl.teachers`,
   where the rules were compared on tuning seeds), and in houses the ``gain`` rule (the path
   cost less twice the unobserved area near the frontier, :attr:`LearnedConfig.teacher_by_id`),
   which leads the nearest frontier there where the other does not: decisions are collected
   with the rules choosing (seeds from :attr:`LearnedConfig.seed`), and the policy is fitted to
   their choices (cross-entropy) and the critic to the discounted returns that followed. The
   policy is not told the building type; its scorer sees, beside each candidate, what the
   decision offers as a whole (:attr:`LearnedConfig.scorer_context`), which tells most of a
   house's decisions from an office's, and a learned summary of all the decision's candidates
   (:attr:`LearnedConfig.scorer_pool`); each id's decisions weigh alike in the cloning loss
   (:attr:`LearnedConfig.bc_balance`: a house has a tenth of a school's decisions).
2. **MaskablePPO** from there, for the rest of the budget.

The log reports decisions/s, primitive steps/s and the share of time collecting against
learning; the model (``.zip``) gets a ``.json`` beside it with the config, the figures and the
CPU it ran on.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass, replace
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from realistic_indoor.agents.rl.config import REALISTIC_IDS
from realistic_indoor.agents.rl.teachers import DEFAULT_TEACHER, TEACHERS
from realistic_indoor.checks import require_bool, require_int, require_positive, require_range
from realistic_indoor.errors import ConfigError
from realistic_indoor.files import atomic_path, write_text
from realistic_indoor.machine import describe_machine

__all__ = [
    "LEARNED_IDS",
    "LEARNED_PRESETS",
    "LearnedConfig",
    "LearnedEnvFactory",
    "learned_env_factories",
    "learned_preset",
    "make_learned_env",
    "train_learned",
]

LEARNED_IDS = REALISTIC_IDS
"""The ids the learned explorer trains on by default, the ``realistic`` set (offices, schools and
houses, at their default sizes and step limits)."""


@dataclass(frozen=True)
class LearnedConfig:
    """A learned-explorer training run.

    Attributes:
        env_ids: Registered ids trained on (their default buildings and step limits). Each of
            the ``n_envs`` environments runs every id, an episode each in turn, environment
            ``i`` starting at id ``i % len(env_ids)``
            (:class:`~realistic_indoor.agents.rl.turns.TakeTurns`): with two environments,
            offices, schools and houses are all trained on.
        n_candidates: Candidate goals per decision (K).
        n_envs: Environments run in parallel (sub-processes when more than one).
        teacher: The rule cloned (a key of :data:`~realistic_indoor.agents.rl.teachers.TEACHERS`)
            in the ids ``teacher_by_id`` does not name (to clone one rule everywhere, set
            ``teacher_by_id=()`` too, as ``train --teacher`` does).
        teacher_by_id: Pairs ``(env id, rule)``: the rule cloned in that id's episodes instead
            of ``teacher`` (by default ``gain`` in houses, where it leads the nearest frontier
            on the tuning seeds and ``teacher`` does not). The policy is not told the id: with
            ``scorer_context`` it can tell a house's decisions by what they offer.
        scorer_context: Give the policy's scorer the decision's figures
            (:data:`~realistic_indoor.agents.rl.scorer.CONTEXT_FEATURES`) beside each candidate.
        scorer_pool: Width of the learned summary of the whole decision the scorer gives every
            candidate (:class:`~realistic_indoor.agents.rl.scorer.CandidateScorer`'s ``pool``;
            0: none). With it the policy follows each id's rule more closely: on held-out
            cloning decisions of seed 0, 87% in houses against 69% without it, 97% in offices
            and schools against 93-95% (95%, 96% and 96% with ``bc_balance`` too).
        bc_balance: Weight the cloned decisions so that every id counts alike in the cloning
            loss (a house has a tenth of a school's decisions: without it the policy learns the
            houses' rule from 6% of the data).
        bc_decisions: Decisions of the teacher's rule collected for behaviour cloning (0: none).
        bc_epochs: Passes of behaviour cloning over them.
        ppo_decisions: Decisions of MaskablePPO training after cloning (0: none).
        seed: Seed of the policy and of the environments' episodes: the ``i``-th environment's
            first episode of its ``p``-th id (in its turns) has the seed ``seed * n_envs *
            len(env_ids) + i + p * n_envs`` (no two runs, environments or ids share one), and
            later episodes continue each environment's random stream (cloning's episodes, then
            PPO's).
        reward_scale: Weight of the ``coverage_auc`` reward (the return is this times the
            coverage AUC minus the coverage at reset).
        n_steps: Decisions per environment per PPO rollout.
        batch_size: Minibatch size (cloning and PPO).
        n_epochs: PPO passes over each rollout.
        learning_rate: Adam step size of PPO.
        bc_learning_rate: Adam step size of cloning.
        gamma: Discount per decision.
        gae_lambda: GAE parameter.
        ent_coef: Entropy bonus.
        clip_range: PPO clipping.
        torch_threads: Threads torch may use in the training process.
    """

    env_ids: tuple[str, ...] = LEARNED_IDS
    n_candidates: int = 16
    n_envs: int = 2
    teacher: str = DEFAULT_TEACHER
    teacher_by_id: tuple[tuple[str, str], ...] = (("HouseExplore-v0", "gain"),)
    scorer_context: bool = True
    scorer_pool: int = 16
    bc_balance: bool = True
    bc_decisions: int = 20_000
    bc_epochs: int = 30
    ppo_decisions: int = 40_000
    seed: int = 0
    reward_scale: float = 100.0
    n_steps: int = 512
    batch_size: int = 256
    n_epochs: int = 4
    learning_rate: float = 1e-4
    bc_learning_rate: float = 1e-3
    gamma: float = 0.995
    gae_lambda: float = 0.95
    ent_coef: float = 0.001
    clip_range: float = 0.1
    torch_threads: int = 1

    def __post_init__(self) -> None:
        from realistic_indoor.envs import PRESETS

        unknown = [e for e in self.env_ids if e not in PRESETS]
        if not self.env_ids or unknown:
            raise ConfigError(
                f"LearnedConfig.env_ids: unknown ids {unknown}; registered: {', '.join(PRESETS)}"
            )
        for name in (
            "n_candidates",
            "n_envs",
            "bc_epochs",
            "n_steps",
            "batch_size",
            "n_epochs",
            "torch_threads",
        ):
            require_int("LearnedConfig", name, getattr(self, name), 1)
        if self.teacher not in TEACHERS:
            raise ConfigError(
                f"LearnedConfig.teacher must be one of {', '.join(TEACHERS)}, got {self.teacher!r}"
            )
        object.__setattr__(self, "teacher_by_id", _rule_pairs(self.teacher_by_id))
        require_bool("LearnedConfig", "scorer_context", self.scorer_context)
        require_bool("LearnedConfig", "bc_balance", self.bc_balance)
        for name in ("bc_decisions", "ppo_decisions", "seed", "scorer_pool"):
            require_int("LearnedConfig", name, getattr(self, name), 0)
        for name in ("reward_scale", "learning_rate", "bc_learning_rate", "clip_range"):
            require_positive("LearnedConfig", name, getattr(self, name), "")
        require_positive("LearnedConfig", "ent_coef", self.ent_coef, "", allow_zero=True)
        require_range("LearnedConfig", "gamma", self.gamma, 0.0, 1.0, "")
        require_range("LearnedConfig", "gae_lambda", self.gae_lambda, 0.0, 1.0, "")
        object.__setattr__(self, "env_ids", tuple(self.env_ids))

    def replace(self, **changes: Any) -> LearnedConfig:
        """A copy with some fields changed (checked again)."""
        return replace(self, **changes)

    def to_dict(self) -> dict[str, Any]:
        """Plain values (for the JSON saved next to a model)."""
        return {
            **asdict(self),
            "env_ids": list(self.env_ids),
            "teacher_by_id": [list(pair) for pair in self.teacher_by_id],
        }

    def rule_for(self, env_id: str) -> str:
        """The rule cloned in ``env_id``'s episodes."""
        return dict(self.teacher_by_id).get(env_id, self.teacher)


LEARNED_PRESETS: dict[str, dict[str, Any]] = {
    "learned": {},
    "learned-house-rule": {"scorer_pool": 0, "bc_balance": False},
    "learned-one-rule": {"teacher_by_id": (), "scorer_context": False, "scorer_pool": 0, "bc_balance": False},
    "learned-smoke": {
        "bc_decisions": 64,
        "bc_epochs": 1,
        "ppo_decisions": 64,
        "n_steps": 32,
        "batch_size": 32,
        "n_epochs": 1,
        "n_envs": 1,
        "env_ids": ("HouseExplore-v0",),
    },
}
"""Named overrides of :class:`LearnedConfig`: ``learned`` (the recipe: 20,000 cloned decisions,
then 40,000 of MaskablePPO), ``learned-house-rule`` (the recipe before the scorer had its learned
summary of the decision and cloning weighed every id alike: the study's ``learned_hr`` models),
``learned-one-rule`` (the recipe before houses had a rule of their own: one rule cloned in every
id, a scorer without the decision's context; the study's ``learned_suas`` models),
``learned-smoke`` (seconds, on houses: checks the set-up)."""


def learned_preset(name: str, **changes: Any) -> LearnedConfig:
    """The config of a preset of :data:`LEARNED_PRESETS`, with ``changes`` on top.

    Raises:
        ConfigError: For an unknown preset or an invalid change.
    """
    if name not in LEARNED_PRESETS:
        raise ConfigError(f"unknown learned preset {name!r}; presets: {', '.join(LEARNED_PRESETS)}")
    return LearnedConfig(**{**LEARNED_PRESETS[name], **changes})


def _rule_pairs(pairs: Any) -> tuple[tuple[str, str], ...]:
    """``pairs`` as a tuple of ``(env id, rule)``, each id once.

    Raises:
        ConfigError: Naming the first pair that is not a registered id with a known rule.
    """
    from realistic_indoor.envs import PRESETS

    hint = f"registered ids: {', '.join(PRESETS)}; rules: {', '.join(TEACHERS)}"
    try:
        items = list(pairs)
    except TypeError:
        raise ConfigError(
            f"LearnedConfig.teacher_by_id must be (env id, rule) pairs, got {pairs!r}"
        ) from None
    out: list[tuple[str, str]] = []
    for pair in items:
        ok = isinstance(pair, (tuple, list)) and len(pair) == 2 and all(isinstance(v, str) for v in pair)
        if not ok or pair[0] not in PRESETS or pair[1] not in TEACHERS:
            raise ConfigError(f"LearnedConfig.teacher_by_id: {pair!r} is not an (env id, rule) pair; {hint}")
        if any(pair[0] == seen for seen, _ in out):
            raise ConfigError(f"LearnedConfig.teacher_by_id names {pair[0]} twice; give each id one rule")
        out.append((pair[0], pair[1]))
    return tuple(out)


class LearnedEnvFactory:
    """Builds one training environment (picklable, for sub-process vector environments).

    Args:
        env_ids: The registered ids it runs, an episode each in turn.
        config: The training run.
        workers: Environments of the run (``config.n_envs``).
        index: This environment's index among them (seeds:
            :class:`~realistic_indoor.agents.rl.turns.TakeTurns`).
    """

    def __init__(
        self, env_ids: Sequence[str], config: LearnedConfig, workers: int = 1, index: int = 0
    ) -> None:
        self.env_ids = tuple(env_ids)
        self.n_candidates = config.n_candidates
        self.reward_scale = config.reward_scale
        self.workers = workers
        self.index = index

    def __call__(self) -> Any:
        """The ids' macro environments in turn, with the metric's reward, filtered keys, a Monitor."""
        from stable_baselines3.common.monitor import Monitor

        from realistic_indoor.agents.rl.turns import TakeTurns

        makers = [partial(make_learned_env, e, self.n_candidates, self.reward_scale) for e in self.env_ids]
        return Monitor(TakeTurns(makers, self.workers, self.index), info_keywords=("coverage",))


def make_learned_env(env_id: str, n_candidates: int = 16, reward_scale: float = 1.0, **kwargs: Any) -> Any:
    """``env_id`` with frontier macro actions, the metric as reward, and the policy's keys only.

    Args:
        env_id: A registered id.
        n_candidates: K.
        reward_scale: Weight of the ``coverage_auc`` reward (every other term 0).
        **kwargs: More ``gym.make`` keywords (``area_m2``, ``max_steps``, ...).
    """
    import gymnasium as gym
    from gymnasium.wrappers import FilterObservation

    import realistic_indoor.envs  # noqa: F401 - registers the ids
    from realistic_indoor.agents.rl.scorer import OBS_KEYS
    from realistic_indoor.envs.rewards import RewardWeights

    rewards = replace(RewardWeights.metric(), coverage_auc=reward_scale)
    env = gym.make(
        env_id, action_type="frontier", macro={"n_candidates": n_candidates}, rewards=rewards, **kwargs
    )
    return FilterObservation(env, list(OBS_KEYS))


def train_learned(
    config: LearnedConfig, out_path: str | Path, log: Callable[[str], object] = print
) -> dict[str, Any]:
    """Train the learned explorer (cloning, then MaskablePPO) and save it to ``out_path`` (``.zip``).

    The model and its ``.json`` (config, decisions, primitive steps, seconds, decisions/s,
    primitive steps/s, the share of time collecting, the machine, and decisions, primitive steps
    and finished episodes per id, ``by_id``) are written whole or not at all.

    Returns:
        The ``.json``'s content.

    Raises:
        ConfigError: If sb3-contrib, stable-baselines3 or torch are missing.
    """
    torch, sb3_contrib = require_learned()
    torch.set_num_threads(config.torch_threads)
    torch.manual_seed(config.seed)
    from realistic_indoor.agents.rl.scorer import CandidatePolicy
    from realistic_indoor.agents.rl.train import ppo_arguments

    out_path = Path(out_path).with_suffix(".zip")
    start = time.perf_counter()
    venv = _vec_env(config, config.seed)
    meter = _Meter()
    try:
        model = sb3_contrib.MaskablePPO(
            CandidatePolicy,
            venv,
            policy_kwargs={"context": config.scorer_context, "pool": config.scorer_pool},
            **ppo_arguments(config),
        )
        bc = _clone(model, venv, config, meter, log) if config.bc_decisions else {}
        if config.ppo_decisions:
            callback = _ppo_callback(meter, log, start)
            model.learn(total_timesteps=config.ppo_decisions, callback=callback, reset_num_timesteps=False)
    finally:
        venv.close()
    seconds = time.perf_counter() - start
    with atomic_path(out_path) as tmp:
        model.save(tmp)
    meta = {
        "config": config.to_dict(),
        "seconds": round(seconds, 1),
        "machine": describe_machine(load=False),
        "behaviour_cloning": bc,
        **meter.summary(seconds),
    }
    write_text(out_path.with_suffix(".json"), json.dumps(meta, indent=1) + "\n")
    log(
        "trained on: "
        + "; ".join(
            f"{k} {v['decisions']:,} decisions, {v['episodes']} episodes" for k, v in meta["by_id"].items()
        )
    )
    log(
        f"saved {out_path} after {seconds:.0f} s: {meter.decisions:,} decisions, {meter.steps:,} primitive "
        f"steps ({meta['decisions_per_s']:.1f} decisions/s, {meta['steps_per_s']:.0f} primitive steps/s "
        f"collecting; collecting {meta['collect_share']:.0%} of the time)"
    )
    return meta


def require_learned() -> tuple[Any, Any]:
    """The modules ``torch`` and ``sb3_contrib``, or a ConfigError naming the install."""
    try:
        import sb3_contrib
        import torch
    except ImportError as e:
        raise ConfigError(
            f'the learned explorer needs sb3-contrib and torch ({e.name} is missing): pip install "realistic-indoor[rl]"'
        ) from None
    return torch, sb3_contrib


class _Meter:
    """Decisions, primitive steps, episodes and time spent collecting."""

    def __init__(self) -> None:
        self.collecting = 0.0
        self.coverages: list[float] = []
        self.by_id: dict[str, dict[str, int]] = {}

    @property
    def decisions(self) -> int:
        return sum(mix["decisions"] for mix in self.by_id.values())

    @property
    def steps(self) -> int:
        return sum(mix["primitive_steps"] for mix in self.by_id.values())

    def add(self, infos: list[dict[str, Any]]) -> None:
        self.coverages.extend(float(i["coverage"]) for i in infos if "episode" in i)
        for info in infos:
            mix = self.by_id.setdefault(
                str(info.get("env_id", "-")), {"decisions": 0, "primitive_steps": 0, "episodes": 0}
            )
            mix["decisions"] += 1
            mix["primitive_steps"] += int(info.get("primitive_steps", 0))
            mix["episodes"] += int("episode" in info)

    def summary(self, seconds: float) -> dict[str, Any]:
        recent = self.coverages[-50:]
        return {
            "decisions": self.decisions,
            "primitive_steps": self.steps,
            "episodes": len(self.coverages),
            "last_coverage": round(sum(recent) / len(recent), 4) if recent else math.nan,
            "collect_seconds": round(self.collecting, 1),
            "decisions_per_s": round(self.decisions / max(self.collecting, 1e-9), 2),
            "steps_per_s": round(self.steps / max(self.collecting, 1e-9), 1),
            "collect_share": round(self.collecting / max(seconds, 1e-9), 3),
            "by_id": dict(sorted(self.by_id.items())),
        }


def learned_env_factories(config: LearnedConfig) -> list[LearnedEnvFactory]:
    """One factory per environment: environment ``i`` runs every id in turn, from id ``i % len(env_ids)``.

    Every id is trained on however few environments there are (with two: offices, schools and
    houses).
    """
    ids, n = config.env_ids, len(config.env_ids)
    return [
        LearnedEnvFactory(ids[i % n :] + ids[: i % n], config, workers=config.n_envs, index=i)
        for i in range(config.n_envs)
    ]


def _vec_env(config: LearnedConfig, seed: int) -> Any:
    from stable_baselines3.common.vec_env import DummyVecEnv, SubprocVecEnv

    factories = learned_env_factories(config)
    venv = SubprocVecEnv(factories, start_method="fork") if config.n_envs > 1 else DummyVecEnv(factories)
    venv.seed(seed)
    return venv


def _clone(model: Any, venv: Any, config: LearnedConfig, meter: _Meter, log: Callable[[str], object]) -> dict:
    """Collect the teacher's decisions, fit the policy to them and the critic to their returns."""
    import torch
    from sb3_contrib.common.maskable.utils import get_action_masks

    obs = venv.reset()
    n_env = venv.num_envs
    store: dict[str, list[np.ndarray]] = {k: [] for k in obs}
    actions, masks, rewards, dones, ids = [], [], [], [], []
    t0 = time.perf_counter()
    while len(actions) * n_env < config.bc_decisions:
        mask = get_action_masks(venv)
        now = venv.get_attr("env_id")
        rules = [TEACHERS[config.rule_for(env_id)] for env_id in now]
        act = np.array([rules[i].choose(obs["candidates"][i], mask[i]) for i in range(n_env)])
        ids.append(now)
        for k in obs:
            store[k].append(obs[k].copy())
        actions.append(act)
        masks.append(mask)
        obs, reward, done, infos = venv.step(act)
        rewards.append(reward)
        dones.append(done)
        meter.add(infos)
    meter.collecting += time.perf_counter() - t0
    returns = _discounted(np.array(rewards), np.array(dones), config.gamma)
    data = {k: torch.as_tensor(np.concatenate(v)) for k, v in store.items()}
    act_t = torch.as_tensor(np.concatenate(actions))
    mask_t = np.concatenate(masks)
    ret_t = torch.as_tensor(returns.reshape(-1), dtype=torch.float32)
    flat_ids = np.asarray(ids).reshape(-1)
    weight_t = torch.as_tensor(
        _id_weights(flat_ids) if config.bc_balance else np.ones(len(flat_ids)), dtype=torch.float32
    )
    policy = model.policy
    optimizer = torch.optim.Adam(policy.parameters(), lr=config.bc_learning_rate)
    n = len(act_t)
    rng = np.random.default_rng(config.seed)
    for epoch in range(config.bc_epochs):
        order = rng.permutation(n)
        total, agree = 0.0, 0
        for lo in range(0, n, config.batch_size):
            idx = order[lo : lo + config.batch_size]
            batch = {k: v[idx] for k, v in data.items()}
            values, log_prob, _ = policy.evaluate_actions(batch, act_t[idx], action_masks=mask_t[idx])
            w = weight_t[idx]
            loss = -(log_prob * w).sum() / w.sum() + 0.5 * torch.nn.functional.mse_loss(
                values.flatten(), ret_t[idx]
            )
            optimizer.zero_grad()
            loss.backward()
            optimizer.step()
            total += float(loss.detach()) * len(idx)
        with torch.no_grad():
            chosen, _, _ = policy.forward(data, deterministic=True, action_masks=mask_t)
            agree = float((chosen == act_t).float().mean())
        log(
            f"cloning epoch {epoch + 1}/{config.bc_epochs}: loss {total / n:.4f}, agrees with the rule on {agree:.1%}"
        )
    same = (chosen == act_t).numpy()
    by_id = {str(e): round(float(same[flat_ids == e].mean()), 4) for e in sorted(set(flat_ids.tolist()))}
    log("agreement by id: " + ", ".join(f"{e} {a:.1%}" for e, a in by_id.items()))
    return {
        "decisions": int(n),
        "seconds": round(time.perf_counter() - t0, 1),
        "agreement": round(agree, 4),
        "agreement_by_id": by_id,
    }


def _id_weights(ids: np.ndarray) -> np.ndarray:
    """A weight per decision such that every id's decisions weigh alike in all, the mean weight 1."""
    names, index, counts = np.unique(ids, return_inverse=True, return_counts=True)
    return len(ids) / (len(names) * counts[index])


def _discounted(rewards: np.ndarray, dones: np.ndarray, gamma: float) -> np.ndarray:
    """Discounted returns per ``(time, env)``, restarting after each episode end (no bootstrap)."""
    out = np.zeros_like(rewards, dtype=float)
    running = np.zeros(rewards.shape[1])
    for t in range(len(rewards) - 1, -1, -1):
        running = rewards[t] + gamma * running * (1.0 - dones[t])
        out[t] = running
    return out


def _ppo_callback(meter: _Meter, log: Callable[[str], object], start: float) -> Any:
    from stable_baselines3.common.callbacks import BaseCallback

    class Progress(BaseCallback):
        """Counts decisions and primitive steps; a log line per rollout."""

        def _on_rollout_start(self) -> None:
            self._t0 = time.perf_counter()

        def _on_rollout_end(self) -> None:
            meter.collecting += time.perf_counter() - self._t0
            s = meter.summary(time.perf_counter() - start)
            log(
                f"PPO {self.num_timesteps:>7} decisions  {time.perf_counter() - start:6.0f} s  "
                f"{s['episodes']} episodes  coverage (last 50) {s['last_coverage']}  "
                f"{s['decisions_per_s']} decisions/s  {s['steps_per_s']} steps/s  collect {s['collect_share']:.0%}"
            )

        def _on_step(self) -> bool:
            meter.add(self.locals["infos"])
            return True

    return Progress()
