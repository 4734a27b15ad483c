"""The configuration of an environment: one frozen dataclass, checked when it is built."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field, fields, replace
from os import PathLike
from pathlib import Path
from typing import Any

from realistic_indoor.building.building import Building
from realistic_indoor.checks import require_int, require_range
from realistic_indoor.envs.actions import ACTION_TYPES
from realistic_indoor.envs.rewards import RewardWeights
from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.lidar import LidarConfig
from realistic_indoor.sim.mapping import LocalMapConfig
from realistic_indoor.sim.robot import RobotConfig
from realistic_indoor.sim.victims import VictimConfig
from realistic_indoor.sim.world import WorldConfig

__all__ = ["BUILDING_TYPES", "TASK_FIELDS", "EnvConfig", "require_task_fields"]

BUILDING_TYPES = ("office", "school", "house", "random")
"""Generators an environment can name in :attr:`EnvConfig.building_type`; ``"random"`` is the
World-Generator-like baseline."""

TASK_FIELDS: dict[str, str] = {"victims": "search", "coverage_target": "explore"}
"""Fields of :class:`EnvConfig` that one task only uses: field name -> that task."""

_SUBCONFIGS = {
    "world": WorldConfig,
    "robot": RobotConfig,
    "lidar": LidarConfig,
    "local_map": LocalMapConfig,
    "rewards": RewardWeights,
    "victims": VictimConfig,
}


@dataclass(frozen=True)
class EnvConfig:
    """Everything that defines an exploration or search environment.

    The building of each episode comes from the first of ``building``, ``plan_path`` and
    ``generator`` that is set, else from the generator named by ``building_type``.

    Attributes:
        building_type: Generator drawing a new building each episode: ``"office"``,
            ``"school"``, ``"house"`` or ``"random"`` (the World-Generator-like baseline).
        area_m2: Floor area asked of the generator (m2); ``None`` for its default.
        generator_params: More keyword arguments for the named generator.
        generator: Any callable ``rng -> Building`` (picklable, for vector environments); it
            replaces the named generator.
        building: One fixed building for every episode (e.g. a real plan).
        plan_path: A plan file (any format :func:`realistic_indoor.io.load` reads), read once
            when the environment is built; the building of every episode.
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
            s each).
        action_type: ``"continuous"`` (``Box(-1, 1, (2,))``) or ``"discrete"``
            (:data:`~realistic_indoor.envs.actions.DISCRETE_ACTIONS`).
    """

    building_type: str = "office"
    area_m2: float | None = None
    generator_params: Mapping[str, Any] = field(default_factory=dict)
    generator: Callable[..., Building] | None = None
    building: Building | None = None
    plan_path: str | Path | None = None
    world: WorldConfig = field(default_factory=WorldConfig)
    robot: RobotConfig = field(default_factory=RobotConfig)
    lidar: LidarConfig = field(default_factory=LidarConfig)
    local_map: LocalMapConfig = field(default_factory=LocalMapConfig)
    rewards: RewardWeights = field(default_factory=RewardWeights)
    victims: VictimConfig = field(default_factory=VictimConfig)
    coverage_target: float = 0.9
    max_steps: int = 1000
    action_type: str = "continuous"

    def __post_init__(self) -> None:
        if self.building_type not in BUILDING_TYPES:
            raise ConfigError(
                f"EnvConfig.building_type: unknown building type {self.building_type!r}; "
                f"valid types: {', '.join(BUILDING_TYPES)}"
            )
        if self.area_m2 is not None:
            require_range("EnvConfig", "area_m2", self.area_m2, 0.0, float("inf"), "m2")
        if self.action_type not in ACTION_TYPES:
            raise ConfigError(
                f"EnvConfig.action_type must be one of {', '.join(ACTION_TYPES)}, got {self.action_type!r}"
            )
        require_range("EnvConfig", "coverage_target", self.coverage_target, 0.0, 1.0, "")
        require_int("EnvConfig", "max_steps", self.max_steps, 1)
        self._check_types()
        self._check_source()

    def _check_types(self) -> None:
        for name, cls in _SUBCONFIGS.items():
            value = getattr(self, name)
            if not isinstance(value, cls):
                raise ConfigError(f"EnvConfig.{name} must be a {cls.__name__}, got {type(value).__name__}")
        if not isinstance(self.generator_params, Mapping):
            raise ConfigError(f"EnvConfig.generator_params must be a mapping, got {self.generator_params!r}")

    def _check_source(self) -> None:
        given = [n for n in ("building", "plan_path", "generator") if getattr(self, n) is not None]
        if len(given) > 1:
            raise ConfigError(
                f"EnvConfig: give at most one building source, got {' and '.join(given)}; "
                "building fixes one building, plan_path reads one, generator draws one per episode"
            )
        if self.building is not None and not isinstance(self.building, Building):
            raise ConfigError(f"EnvConfig.building must be a Building, got {type(self.building).__name__}")
        if self.plan_path is not None and not isinstance(self.plan_path, (str, PathLike)):
            raise ConfigError(f"EnvConfig.plan_path must be a file path, got {self.plan_path!r}")
        if self.generator is not None and not callable(self.generator):
            raise ConfigError(
                f"EnvConfig.generator must be a callable rng -> Building, got {self.generator!r}"
            )

    def replace(self, **changes: Any) -> EnvConfig:
        """A copy with some fields changed (checked again).

        A sub-config (``world``, ``robot``, ``lidar``, ``local_map``, ``rewards``, ``victims``)
        may be given as a mapping of the fields to change in it, e.g.
        ``replace(lidar={"n_beams": 64})``. Setting one building source (``building``,
        ``plan_path`` or ``generator``) clears the others, so that a preset's source can be
        overridden by any of them.

        Raises:
            ConfigError: If a field name is unknown or a value is invalid.
        """
        known = {f.name for f in fields(self)}
        _require_known("EnvConfig", changes, known)
        for name, cls in _SUBCONFIGS.items():
            if isinstance(changes.get(name), Mapping):
                current = getattr(self, name)
                _require_known(cls.__name__, changes[name], {f.name for f in fields(cls)})
                changes[name] = replace(current, **changes[name])
        sources = {"building", "plan_path", "generator"}
        if sources & {k for k, v in changes.items() if v is not None}:
            changes = {**dict.fromkeys(sources), **changes}
        return replace(self, **changes)


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
