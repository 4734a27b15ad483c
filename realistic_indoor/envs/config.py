"""The configuration of an environment: one frozen dataclass, checked when it is built."""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field, fields, replace
from typing import TYPE_CHECKING, Any

from realistic_indoor.checks import require_between, require_int
from realistic_indoor.envs.actions import ACTION_TYPES, PRIMITIVE_ACTION_TYPES
from realistic_indoor.envs.macro import MacroConfig
from realistic_indoor.envs.observations import EXTRA_OBSERVATIONS, GlobalMapConfig
from realistic_indoor.envs.rewards import RewardWeights
from realistic_indoor.envs.source import (
    GENERATED_KEYWORDS,
    SOURCE_KEYWORDS,
    BuildingSource,
    GeneratedBuildings,
    as_source,
    source_from_keywords,
)
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.lidar import LidarConfig
from realistic_indoor.sim.mapping import LocalMapConfig
from realistic_indoor.sim.robot import RobotConfig
from realistic_indoor.sim.victims import VictimConfig
from realistic_indoor.sim.world import WorldConfig

if TYPE_CHECKING:
    import numpy as np

__all__ = ["MAX_STEPS", "TASK_FIELDS", "EnvConfig", "require_reset_options", "require_task_fields"]

MAX_STEPS = 1_000_000
"""Largest ``EnvConfig.max_steps``: more than 55 hours of robot time at 5 Hz; the presets give at
most 15,000 steps to buildings of the default sizes."""

TASK_FIELDS: dict[str, str] = {"victims": "search", "coverage_target": "explore"}
"""Fields of :class:`EnvConfig` that one task only uses: field name -> that task."""

_SUBCONFIGS = {
    "world": WorldConfig,
    "robot": RobotConfig,
    "lidar": LidarConfig,
    "local_map": LocalMapConfig,
    "rewards": RewardWeights,
    "victims": VictimConfig,
    "macro": MacroConfig,
    "global_map": GlobalMapConfig,
}


@dataclass(frozen=True)
class EnvConfig:
    """Everything that defines an exploration or search environment.

    Where each episode's building comes from is one field, ``source`` (see
    :mod:`realistic_indoor.envs.source`). The keywords that chose it before it existed are still
    accepted by the constructor and :meth:`replace`, and mapped onto it: ``building_type``,
    ``area_m2`` and ``generator_params`` set a :class:`GeneratedBuildings` source's type, area and
    options; ``generator``, ``building`` or ``plan_path`` replaces the source by a
    :class:`~realistic_indoor.envs.source.CustomGenerator`,
    :class:`~realistic_indoor.envs.source.FixedBuilding` or
    :class:`~realistic_indoor.envs.source.PlanFile`.

    Attributes:
        source: Where each episode's building comes from: a
            :data:`~realistic_indoor.envs.source.BuildingSource`, or a shorthand for one (a
            building type name such as ``"school"``, a ``Building``, a plan file's path, a
            callable ``rng -> Building``); default: generated offices of the default area.
        world: Raster resolution (m per cell, also the robot's map resolution), wall
            thickness (m) and start clearance (m).
        robot: Disc radius (m), speed and turn limits (m/s, rad/s), accelerations, control
            rate (Hz) and physics sub-steps per control step.
        lidar: Field of view (rad), number of beams, maximum range (m), range noise (m).
        local_map: Side (pixels, >= 36 for stable-baselines3's ``CnnPolicy``) and pixel size
            (m) of the egocentric map image.
        rewards: Weight of each reward term.
        victims: Number of victims, the rooms they may be in, and the victim sensor's range
            (m) and field of view (rad); search environments only (an exploration
            environment refuses it).
        coverage_target: Share of the reachable floor whose observation ends an exploration
            episode, in ``(0, 1]``; exploration environments only (a search environment,
            which ends when every victim is found, refuses it).
        max_steps: Control steps after which an episode is truncated (``1 / robot.control_hz``
            s each), an integer in [1, 1000000] (more than 55 hours of robot time at 5 Hz).
        action_type: ``"continuous"`` (``Box(-1, 1, (2,))``), ``"discrete"``
            (:data:`~realistic_indoor.envs.actions.DISCRETE_ACTIONS`), ``"frontier"``
            (``Discrete(macro.n_candidates)``: a candidate goal, driven to by the explorers'
            navigator) or ``"waypoint"`` (``Discrete(macro.waypoint_grid ** 2)``: a cell of a grid
            around the robot); :mod:`realistic_indoor.envs.macro`.
        macro: Candidates per decision, the waypoint grid and the navigator's settings, for
            the macro action types (ignored otherwise).
        extra_observations: Observation keys added to the task's own: any of ``"global_map"``
            (the robot's whole map around it, start heading up: :attr:`global_map`),
            ``"candidates"`` (frontier macro actions only) and ``"time_left"`` (the share of the
            step limit left). ``None``: the action type's default: ``("candidates",
            "time_left")`` with frontier actions, ``("global_map", "time_left")`` with waypoint
            actions, none with primitive ones.
        global_map: Size (pixels) and pixel side (m) of the ``global_map`` observation.
    """

    source: BuildingSource = field(default_factory=GeneratedBuildings)
    world: WorldConfig = field(default_factory=WorldConfig)
    robot: RobotConfig = field(default_factory=RobotConfig)
    lidar: LidarConfig = field(default_factory=LidarConfig)
    local_map: LocalMapConfig = field(default_factory=LocalMapConfig)
    rewards: RewardWeights = field(default_factory=RewardWeights)
    victims: VictimConfig = field(default_factory=VictimConfig)
    coverage_target: float = 0.9
    max_steps: int = 1000
    action_type: str = "continuous"
    macro: MacroConfig = field(default_factory=MacroConfig)
    extra_observations: tuple[str, ...] | None = None
    global_map: GlobalMapConfig = field(default_factory=GlobalMapConfig)

    def __post_init__(self) -> None:
        object.__setattr__(self, "source", as_source(self.source))
        if self.action_type not in ACTION_TYPES:
            raise ConfigError(
                f"EnvConfig.action_type must be one of {', '.join(ACTION_TYPES)}, got {self.action_type!r}"
            )
        self._check_extra_observations()
        require_between("EnvConfig", "coverage_target", self.coverage_target, 0.0, 1.0, "", low_open=True)
        require_int("EnvConfig", "max_steps", self.max_steps, 1, MAX_STEPS)
        self._check_types()

    @property
    def observation_extras(self) -> tuple[str, ...]:
        """The extra observation keys in force: :attr:`extra_observations`, or the action type's default."""
        if self.extra_observations is not None:
            return self.extra_observations
        return {"frontier": ("candidates", "time_left"), "waypoint": ("global_map", "time_left")}.get(
            self.action_type, ()
        )

    def _check_extra_observations(self) -> None:
        extras = self.extra_observations
        if extras is None:
            return
        if isinstance(extras, str) or not all(isinstance(k, str) for k in extras):
            raise ConfigError(
                f"EnvConfig.extra_observations must be a tuple of names ({', '.join(EXTRA_OBSERVATIONS)}), "
                f"got {extras!r}"
            )
        unknown = [k for k in extras if k not in EXTRA_OBSERVATIONS]
        if unknown:
            raise ConfigError(
                f"EnvConfig.extra_observations: unknown {', '.join(map(repr, unknown))}; "
                f"valid: {', '.join(EXTRA_OBSERVATIONS)}"
            )
        if "candidates" in extras and self.action_type != "frontier":
            raise ConfigError(
                "EnvConfig.extra_observations: 'candidates' needs frontier macro actions (action_type='frontier'), "
                f"got action_type {self.action_type!r}"
            )
        object.__setattr__(self, "extra_observations", tuple(dict.fromkeys(extras)))

    def _check_types(self) -> None:
        for name, cls in _SUBCONFIGS.items():
            value = getattr(self, name)
            if not isinstance(value, cls):
                raise ConfigError(f"EnvConfig.{name} must be a {cls.__name__}, got {type(value).__name__}")

    def batch_refusal(self) -> tuple[str, str] | None:
        """What of this configuration the vector and team envs' batched simulation does not run.

        The single env runs every configuration: the compiled physics on a batch of one, pymunk
        one class after the other.

        Returns:
            ``None`` if it runs all of it, else ``(kind, what)``: ``kind`` one of ``"physics"``
            (pymunk: the batch runs the compiled physics only), ``"actions"`` (macro actions:
            it runs primitive ones), ``"observations"`` (extra observations) or ``"reward"``
            (the ``coverage_auc`` term), and ``what`` the setting, as a message names it.
        """
        if self.robot.physics != "compiled":
            return "physics", f"robot physics {self.robot.physics!r} (only the compiled physics runs batched)"
        if self.action_type not in PRIMITIVE_ACTION_TYPES:
            return (
                "actions",
                f"action_type {self.action_type!r} (only primitive actions, continuous or discrete, run batched)",
            )
        if self.observation_extras:
            return "observations", f"the extra observations {list(self.observation_extras)}"
        if self.rewards.coverage_auc != 0.0:
            return "reward", "the coverage_auc reward term"
        return None

    def explored(self, coverage: float | np.ndarray) -> bool | np.ndarray:
        """Whether ``coverage`` (a share, or an array of them) ends an exploration episode.

        The rule of every exploration environment, single, vector or team: the coverage target
        is reached.
        """
        return coverage >= self.coverage_target

    def replace(self, **changes: Any) -> EnvConfig:
        """A copy with some fields changed (checked again).

        A sub-config (``world``, ``robot``, ``lidar``, ``local_map``, ``rewards``, ``victims``, ``macro``)
        may be given as a mapping of the fields to change in it, e.g.
        ``replace(lidar={"n_beams": 64})``. The older source keywords (``building_type``,
        ``area_m2``, ``generator_params``, ``generator``, ``building``, ``plan_path``) change
        ``source`` as the class docstring says.

        Raises:
            ConfigError: If a field name is unknown, a value is invalid, or the source is given
                twice (``source`` with ``building``, say).
        """
        known = {f.name for f in fields(self)} | set(_OLD_SOURCE_KEYWORDS)
        _require_known("EnvConfig", changes, known)
        for name, cls in _SUBCONFIGS.items():
            if isinstance(changes.get(name), Mapping):
                current = getattr(self, name)
                _require_known(cls.__name__, changes[name], {f.name for f in fields(cls)})
                changes[name] = replace(current, **changes[name])
        old = {k: changes.pop(k) for k in _OLD_SOURCE_KEYWORDS if k in changes}
        if old:
            base = as_source(changes["source"]) if "source" in changes else self.source
            changes["source"] = _apply_old_keywords(base, "source" in changes, old)
        return replace(self, **changes)


_OLD_SOURCE_KEYWORDS = (*GENERATED_KEYWORDS, *SOURCE_KEYWORDS)


def _accept_old_source_keywords(init: Callable[..., None]) -> Callable[..., None]:
    """Wrap the dataclass constructor so that it maps the older source keywords onto ``source``."""

    @functools.wraps(init)
    def wrapped(self: EnvConfig, *args: Any, **kwargs: Any) -> None:
        old = {k: kwargs.pop(k) for k in _OLD_SOURCE_KEYWORDS if k in kwargs}
        init(self, *args, **kwargs)
        if old:
            explicit = "source" in kwargs or bool(args)
            object.__setattr__(self, "source", _apply_old_keywords(self.source, explicit, old))

    return wrapped


def _apply_old_keywords(source: BuildingSource, explicit: bool, old: Mapping[str, Any]) -> BuildingSource:
    """``source`` changed by the older keywords; ``explicit``: it was given in the same call."""
    chosen = [k for k in (*SOURCE_KEYWORDS, "building_type") if old.get(k) is not None]
    if explicit and chosen:
        raise ConfigError(f"EnvConfig: give the building source once, got source and {chosen[0]}")
    return source_from_keywords(source, old)


EnvConfig.__init__ = _accept_old_source_keywords(EnvConfig.__init__)  # type: ignore[method-assign]


def _require_known(owner: str, changes: Mapping[str, Any], known: set[str]) -> None:
    unknown = sorted(set(changes) - known)
    if unknown:
        raise ConfigError(f"{owner} has no field {unknown[0]!r}; fields: {', '.join(sorted(known))}")


def require_task_fields(config: EnvConfig, task: str, named: Iterable[str] = ()) -> None:
    """Refuse the fields of :data:`TASK_FIELDS` that ``task`` does not use.

    Such a field may be neither named as a keyword (even with its default value) nor changed
    from its default in ``config``: it would be silently ignored.

    Args:
        config: The environment's configuration.
        task: ``"explore"`` or ``"search"``.
        named: The keywords the user gave (``gym.make`` or constructor overrides).

    Raises:
        ConfigError: If a field of another task is named or set, naming the field and the
            ids that use it.
    """
    defaults = EnvConfig()
    for name, owner in TASK_FIELDS.items():
        if owner != task and (name in named or getattr(config, name) != getattr(defaults, name)):
            raise ConfigError(
                f"{name!r} applies to {owner} environments only ({owner.capitalize()} ids such as "
                f"Office{owner.capitalize()}-v0), not to this {task} environment; remove it"
            )


def require_reset_options(options: Mapping[str, Any] | None, known: Iterable[str]) -> dict[str, Any]:
    """``reset``'s options, refused if one is not ``known``; ``{}`` for ``None``.

    Raises:
        ConfigError: Naming the first unknown option and the known ones.
    """
    options = dict(options or {})
    known = sorted(known)
    unknown = sorted(set(options) - set(known))
    if unknown:
        raise ConfigError(f"unknown reset option {unknown[0]!r}; known: {', '.join(known)}")
    return options
