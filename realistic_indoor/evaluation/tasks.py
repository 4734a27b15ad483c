"""What an evaluation runs: environments (registered ids, possibly on fixed plans) and episodes."""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from realistic_indoor.errors import ConfigError, PlanFormatError

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building
    from realistic_indoor.validator.plan_sets import SkippedPlan

__all__ = [
    "PLAN_SUFFIXES",
    "EnvSpec",
    "EpisodeTask",
    "check_robots",
    "make_env",
    "make_tasks",
    "make_team_env",
    "parse_envs",
    "readable_envs",
    "task_key",
]

PLAN_SUFFIXES = (".xml", ".json")
"""Files taken as plans when an environment names a folder (``.wg.xml`` ends in ``.xml``)."""


@dataclass(frozen=True)
class EnvSpec:
    """One environment of an evaluation.

    Attributes:
        env_id: A registered id (``OfficeExplore-v0``, ...).
        plan: A plan file run as the fixed building of every episode (read with entrances
            inferred, as real plans have none); ``None`` for the id's generator.
        kwargs: More keyword arguments of ``gym.make`` (``area_m2``, ``max_steps``, ...).
        label: Name of this environment in results (the id, or ``id:plan-stem``).
        group: Name of the set it belongs to in summaries (the id, ``id:plan-stem`` for one plan
            file, or ``id:folder``).
    """

    env_id: str
    plan: str | None = None
    kwargs: dict[str, Any] = field(default_factory=dict)
    label: str = ""
    group: str = ""

    def __post_init__(self) -> None:
        stem = None if self.plan is None else Path(self.plan).stem
        if not self.label:
            object.__setattr__(self, "label", self.env_id if stem is None else f"{self.env_id}:{stem}")
        if not self.group:
            object.__setattr__(self, "group", self.label)


@dataclass(frozen=True)
class EpisodeTask:
    """One episode: an agent in an environment with a seed.

    Attributes:
        agent: Agent name (see :func:`realistic_indoor.agents.make_agent`).
        env: The environment.
        seed: Seed of ``env.reset`` and of the agent.
        curve_every_steps: Coverage is recorded every this many steps.
        curve_every_m: ... and every this many metres driven.
        target: Coverage whose first crossing is timed (``time_to_target_s``).
        robots: ``None`` runs the agent alone in the single environment; ``n`` runs a team
            agent (:func:`realistic_indoor.agents.team.make_team_agent`) with ``n`` robots in
            the id's team environment (:func:`realistic_indoor.teams.parallel_env`).
    """

    agent: str
    env: EnvSpec
    seed: int
    curve_every_steps: int = 10
    curve_every_m: float = 2.0
    target: float = 0.9
    robots: int | None = None


def parse_envs(tokens: list[str], kwargs: dict[str, Any] | None = None) -> list[EnvSpec]:
    """Environments from ``ID`` or ``ID:PLAN`` tokens, where ``PLAN`` is a plan file or a folder.

    A folder gives one environment per plan file below it (recursively, sorted, hidden files
    left out), labelled ``ID:stem`` (``ID:sub/stem`` where two plans share a stem) and grouped
    as ``ID:folder``. The plans are not read here: see :func:`readable_envs`.

    Args:
        tokens: E.g. ``["OfficeExplore-v0", "OfficeExplore-v0:../shared/data/real_floorplans/office"]``.
        kwargs: Keyword arguments of ``gym.make`` for every environment.

    Raises:
        ConfigError: For an unknown id, a plan path that does not exist, or a folder without plans.
    """
    from realistic_indoor.envs import PRESETS
    from realistic_indoor.validator.plan_sets import plan_files

    specs = []
    for token in tokens:
        env_id, colon, plan = token.strip().partition(":")
        if env_id not in PRESETS:
            raise ConfigError(f"unknown environment id {env_id!r}; registered: {', '.join(PRESETS)}")
        if colon and not plan.strip():
            raise ConfigError(f"{token!r}: nothing after ':'; give a plan file or folder ({env_id}:<plan>)")
        if not plan:
            specs.append(EnvSpec(env_id, None, dict(kwargs or {})))
            continue
        path = Path(plan)
        if path.is_dir():
            files = plan_files(path)
            if not files:
                raise ConfigError(f"no plan files ({', '.join(PLAN_SUFFIXES)}) in folder {plan!r}")
            group = f"{env_id}:{path.name}"
            specs += [
                EnvSpec(env_id, str(f), dict(kwargs or {}), label=f"{env_id}:{name}", group=group)
                for f, name in zip(files, _plan_names(path, files), strict=True)
            ]
        elif path.is_file():
            specs.append(EnvSpec(env_id, str(path), dict(kwargs or {})))
        else:
            raise ConfigError(f"plan {plan!r} of {token!r} is neither a file nor a folder")
    return specs


def _plan_names(folder: Path, files: list[Path]) -> list[str]:
    """Each plan's stem, or its path below ``folder`` without the ending where stems repeat."""
    stems = [f.stem for f in files]
    return [
        f.stem if stems.count(f.stem) == 1 else f.relative_to(folder).with_suffix("").as_posix()
        for f in files
    ]


def readable_envs(specs: list[EnvSpec], strict: bool = False) -> tuple[list[EnvSpec], list[SkippedPlan]]:
    """The environments whose plan can be read and used; the others are left out with a warning.

    Each plan is read once (and kept for :func:`make_env` in this process). A plan that cannot
    be read, or has no rooms, is left out with a
    :class:`~realistic_indoor.validator.plan_sets.SkippedPlanWarning` naming it.

    Args:
        specs: The environments (those without a plan are kept as they are).
        strict: Raise at the first plan that cannot be read, has no rooms, or would need repair
            (floor-plan XML read with ``strict``), instead of leaving it out.

    Returns:
        The environments kept, in order, and the plans left out.

    Raises:
        PlanFormatError: Under ``strict``, for the first plan that cannot be read or used.
        ConfigError: If every environment had a plan and none is left.
    """
    from realistic_indoor.validator.plan_sets import PlanBatch

    plans = list(dict.fromkeys(s.plan for s in specs if s.plan is not None))
    batch = PlanBatch(plans, strict=strict, reader=lambda p: _usable_plan(str(p), strict))
    usable = {str(path) for path, _building in batch}
    kept = [s for s in specs if s.plan is None or s.plan in usable]
    if not kept:
        first = batch.skipped[0]
        raise ConfigError(f"none of the {len(plans)} plans can be used, e.g. {first.source}: {first.reason}")
    return kept, batch.skipped


def _usable_plan(path: str, strict: bool) -> Building:
    """The plan at ``path``, read as :func:`make_env` reads it, if an environment can be built on it."""
    building = _load_plan(path, strict)
    if not building.rooms:
        raise PlanFormatError(path, "the plan has no rooms")
    return building


def make_tasks(
    agents: list[str],
    envs: list[EnvSpec],
    episodes: int,
    seed: int = 0,
    robots: Sequence[int] | None = None,
    **options: Any,
) -> list[EpisodeTask]:
    """Every agent in every environment for ``episodes`` seeds (``seed``, ``seed + 1``, ...).

    All agents meet the same seeds, hence the same buildings: comparisons are paired. With
    ``robots``, every agent runs as a team of each size in turn (the same seeds for each).

    Raises:
        ConfigError: If there is no agent, no environment, fewer than one episode, or a team
            size that is not an integer in [1, :data:`realistic_indoor.teams.MAX_ROBOTS`].
    """
    if not agents or not envs:
        raise ConfigError("an evaluation needs at least one agent and one environment")
    if isinstance(episodes, bool) or not isinstance(episodes, int) or episodes < 1:
        raise ConfigError(f"episodes must be an integer >= 1, got {episodes!r}")
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise ConfigError(
            f"seed must be an integer >= 0 (environments take non-negative seeds), got {seed!r}"
        )
    sizes: list[int | None] = [None] if robots is None else check_robots(robots)
    return [
        EpisodeTask(a, e, seed + i, robots=n, **options)
        for a in agents
        for n in sizes
        for e in envs
        for i in range(episodes)
    ]


def check_robots(robots: Sequence[int]) -> list[int]:
    """Team sizes, checked: distinct integers in [1, :data:`realistic_indoor.teams.MAX_ROBOTS`], in order.

    Raises:
        ConfigError: For none, a repeat, or a size that is not such an integer.
    """
    from realistic_indoor.teams import MAX_ROBOTS

    sizes = list(robots)
    if not sizes:
        raise ConfigError("robots names no team size; give one or more, e.g. 1,2,4,8")
    for n in sizes:
        if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= MAX_ROBOTS:
            raise ConfigError(f"team sizes must be integers from 1 to {MAX_ROBOTS}, got {n!r}")
    if len(set(sizes)) < len(sizes):
        raise ConfigError(f"team sizes repeat: {', '.join(map(str, sizes))}")
    return sizes


def task_key(task: EpisodeTask) -> tuple[str, str, int, int | None]:
    """What identifies an episode in results: ``(agent, environment label, seed, robots)``."""
    return task.agent, task.env.label, task.seed, task.robots


def make_env(spec: EnvSpec, extra_observations: tuple[str, ...] = ()) -> Any:
    """``gym.make`` of an environment spec; a plan is loaded once per process and reused.

    Args:
        spec: The environment.
        extra_observations: Extra observations an agent reads
            (:func:`~realistic_indoor.agents.agent_observations`), added to the spec's own.

    Raises:
        PlanFormatError: If the plan cannot be read.
        ConfigError: If a keyword argument is invalid.
    """
    import gymnasium as gym

    import realistic_indoor.envs  # noqa: F401 - registers the ids

    kwargs = _spec_kwargs(spec)
    if extra_observations:
        asked = tuple(kwargs.get("extra_observations") or ())
        kwargs["extra_observations"] = tuple(dict.fromkeys(asked + tuple(extra_observations)))
    if "max_steps" in kwargs:
        kwargs.setdefault("max_episode_steps", kwargs["max_steps"])
    return gym.make(spec.env_id, **kwargs)


def make_team_env(spec: EnvSpec, robots: int) -> Any:
    """The team environment of ``robots`` robots on an environment spec.

    The spec's keyword arguments may name the team's ``comm`` and ``map_sharing``
    (:func:`realistic_indoor.teams.parallel_env`'s; ``"wss"`` and ``"comm"`` by default).

    Raises:
        PlanFormatError: If the plan cannot be read.
        ConfigError: If a keyword argument is invalid.
        DependencyNotInstalled: Without PettingZoo (the ``teams`` extra).
    """
    from realistic_indoor import teams

    kwargs = _spec_kwargs(spec)
    links = {k: kwargs.pop(k) for k in ("comm", "map_sharing") if k in kwargs}
    return teams.parallel_env(spec.env_id, n_robots=robots, **links, **kwargs)


def _spec_kwargs(spec: EnvSpec) -> dict[str, Any]:
    """The spec's keyword arguments (a copy), with its plan as the fixed ``building``.

    The plan comes from the cache entry :func:`readable_envs` filled: it is read (and its repairs
    shown) once per process.
    """
    kwargs = dict(spec.kwargs)
    if spec.plan is not None:
        kwargs["building"] = _load_plan(spec.plan, False)
    return kwargs


@functools.lru_cache(maxsize=64)
def _load_plan(path: str, strict: bool = False) -> Building:
    """A plan; floor-plan XML (real plans, without exterior doors) gets its entrances inferred.

    ``strict`` refuses a floor-plan XML plan that would need repair (see
    :func:`~realistic_indoor.validator.plan_sets.read_plan`).
    """
    from realistic_indoor.validator.plan_sets import read_plan

    return read_plan(path, strict=strict, infer_entrances=True)
