"""Plausible bounds on every physical setting (issue 35 item 3).

The ranges below are those of ``docs/failures.md`` ("Plausible bounds") and of the fields'
docstrings, written out again here rather than read from the code: each config takes its
defaults and both edges of each range, and refuses a value just outside, NaN, infinities and
bools with one ``ConfigError`` line naming the class, the field and the range.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pytest

from realistic_indoor.checks import require_between, require_int, require_positive, require_range
from realistic_indoor.envs.config import EnvConfig
from realistic_indoor.envs.observations import GlobalMapConfig
from realistic_indoor.errors import ConfigError
from realistic_indoor.io.world3d.scene import WorldOptions
from realistic_indoor.sim.lidar import LidarConfig
from realistic_indoor.sim.mapping import LocalMapConfig
from realistic_indoor.sim.robot import RobotConfig
from realistic_indoor.sim.victims import VictimConfig
from realistic_indoor.sim.world import WorldConfig

TWO_PI = 2 * math.pi


@dataclass(frozen=True)
class Bound:
    """One documented range: ``text`` as the message writes it, ``low``/``high`` as numbers.

    ``context`` holds other fields that let an edge pass a cross-field check (a fast robot
    needs more physics sub-steps; a 10 m door needs 10 m walls).
    """

    cls: type
    name: str
    low: float
    high: float
    text: str
    integer: bool = False
    low_open: bool = False
    context: dict[str, Any] = field(default_factory=dict)

    @property
    def id(self) -> str:
        return f"{self.cls.__name__}.{self.name}"

    def make(self, value: Any) -> Any:
        return self.cls(**{**self.context, self.name: value})


BOUNDS = [
    Bound(RobotConfig, "radius_m", 0.05, 2.0, "[0.05, 2] m", context={"max_speed_m_s": 0.1}),
    Bound(RobotConfig, "max_speed_m_s", 0.05, 5.0, "[0.05, 5] m/s", context={"substeps": 40}),
    Bound(RobotConfig, "max_turn_rate_rad_s", 0.1, 10.0, "[0.1, 10] rad/s"),
    Bound(RobotConfig, "max_accel_m_s2", 0.1, 10.0, "[0.1, 10] m/s2"),
    Bound(RobotConfig, "max_angular_accel_rad_s2", 0.1, 50.0, "[0.1, 50] rad/s2"),
    Bound(RobotConfig, "control_hz", 1.0, 100.0, "[1, 100] Hz", context={"substeps": 10}),
    Bound(RobotConfig, "substeps", 1, 1000, "[1, 1000]", integer=True, context={"max_speed_m_s": 0.5}),
    Bound(LidarConfig, "fov_rad", 0.0, TWO_PI, "(0, 6.28319] rad", low_open=True),
    Bound(LidarConfig, "n_beams", 1, 3600, "[1, 3600]", integer=True),
    Bound(LidarConfig, "max_range_m", 0.1, 100.0, "[0.1, 100] m"),
    Bound(LidarConfig, "noise_std_m", 0.0, 1.0, "[0, 1] m"),
    Bound(WorldConfig, "resolution_m", 0.01, 1.0, "[0.01, 1] m"),
    Bound(WorldConfig, "wall_thickness_m", 0.0, 1.0, "[0, 1] m"),
    Bound(WorldConfig, "margin_m", 0.0, 10.0, "[0, 10] m"),
    Bound(WorldConfig, "start_clearance_m", 0.05, 3.0, "[0.05, 3] m"),
    Bound(LocalMapConfig, "size_px", 1, 1024, "[1, 1024]", integer=True),
    Bound(LocalMapConfig, "resolution_m", 0.01, 2.0, "[0.01, 2] m"),
    Bound(GlobalMapConfig, "size_px", 8, 1024, "[8, 1024]", integer=True),
    Bound(GlobalMapConfig, "resolution_m", 0.01, 5.0, "[0.01, 5] m"),
    Bound(VictimConfig, "n_victims", 1, 1000, "[1, 1000]", integer=True),
    Bound(VictimConfig, "min_clearance_m", 0.0, 5.0, "[0, 5] m"),
    Bound(VictimConfig, "sensor_range_m", 0.1, 50.0, "[0.1, 50] m"),
    Bound(VictimConfig, "sensor_fov_rad", 0.0, TWO_PI, "(0, 6.28319] rad", low_open=True),
    Bound(WorldOptions, "wall_height_m", 0.1, 10.0, "[0.1, 10] m"),
    Bound(WorldOptions, "wall_thickness_m", 0.01, 1.0, "[0.01, 1] m"),
    Bound(WorldOptions, "door_height_m", 0.1, 10.0, "[0.1, 10] m", context={"wall_height_m": 10.0}),
    Bound(EnvConfig, "coverage_target", 0.0, 1.0, "(0, 1]", low_open=True),
    Bound(EnvConfig, "max_steps", 1, 1_000_000, "[1, 1000000]", integer=True),
]
IDS = [b.id for b in BOUNDS]


def _edges(b: Bound) -> list[float]:
    """The values at the edges of the range that must pass."""
    low = math.nextafter(b.low, math.inf) if b.low_open else b.low
    return [low, b.high]


def _outside(b: Bound) -> list[Any]:
    """Values just outside the range."""
    if b.integer:
        return [b.low - 1, b.high + 1]
    low = b.low if b.low_open else math.nextafter(b.low, -math.inf)
    return [low, math.nextafter(b.high, math.inf), b.low - 1.0, b.high * 100]


def _not_numbers(b: Bound) -> list[Any]:
    """NaN, infinities, bools and other non-numbers (floats too, for an integer field).

    ``None`` too, unless it is the field's default (``WorldOptions.door_height_m``: the
    default height).
    """
    values: list[Any] = [math.nan, math.inf, -math.inf, True, False, "1"]
    if b.cls.__dataclass_fields__[b.name].default is not None:
        values.append(None)
    if b.integer:
        values += [float(b.low), b.low + 0.5]
    return values


def _message(b: Bound) -> str:
    kind = "an integer" if b.integer else "a finite number"
    return f"{b.id} must be {kind} in {b.text}"


@pytest.mark.parametrize("cls", sorted({b.cls for b in BOUNDS}, key=lambda c: c.__name__))
def test_defaults__pass(cls):
    cls()


@pytest.mark.parametrize("b", BOUNDS, ids=IDS)
def test_edges_of_the_range__pass(b):
    for value in _edges(b):
        assert getattr(b.make(value), b.name) == value


@pytest.mark.parametrize("b", BOUNDS, ids=IDS)
def test_value_just_outside__is_refused_naming_class_field_and_range(b):
    for value in _outside(b):
        with pytest.raises(ConfigError) as info:
            b.make(value)
        message = str(info.value)
        assert message.startswith(_message(b)), message
        assert message.endswith(f"got {value!r}") and "\n" not in message


@pytest.mark.parametrize("b", BOUNDS, ids=IDS)
def test_nan_inf_bool_and_non_numbers__are_refused(b):
    for value in _not_numbers(b):
        with pytest.raises(ConfigError, match=f"^{b.id} must be"):
            b.make(value)


def test_numpy_numbers__pass():
    assert RobotConfig(radius_m=np.float32(0.3)).radius_m == pytest.approx(0.3)
    assert LidarConfig(n_beams=np.int64(37)).n_beams == 37


def test_the_absurd_robot_of_the_issue__is_refused():
    with pytest.raises(
        ConfigError, match=r"^RobotConfig.radius_m must be a finite number in \[0.05, 2\] m, got 100.0$"
    ):
        RobotConfig(radius_m=100.0)


def test_every_preset__is_inside_the_bounds():
    from realistic_indoor.envs.presets import PRESETS, preset_config

    for env_id in PRESETS:
        preset_config(env_id)


def test_a_bound_in_a_nested_config__fails_the_environment_config():
    with pytest.raises(
        ConfigError, match=r"^RobotConfig.max_speed_m_s must be a finite number in \[0.05, 5\] m/s"
    ):
        EnvConfig().replace(robot={"max_speed_m_s": 50.0})


# -- the helpers ---------------------------------------------------------------------------------


def test_require_between__message_and_open_low_end():
    with pytest.raises(ConfigError, match=r"^A.b must be a finite number in \[0.05, 2\] m, got 100.0$"):
        require_between("A", "b", 100.0, 0.05, 2.0, "m")
    with pytest.raises(ConfigError, match=r"^A.b must be a finite number in \(0, 1\], got 0$"):
        require_between("A", "b", 0, 0.0, 1.0, "", low_open=True)
    with pytest.raises(ConfigError, match=r"^--flag must be a finite number in \[1, 2\] m, got 3$"):
        require_between("", "--flag", 3, 1, 2, "m")
    require_between("A", "b", 0.0, 0.0, 1.0, "")
    require_between("A", "b", 1, 0.0, 1.0, "")


def test_older_helpers__behave_as_before():
    with pytest.raises(ConfigError, match=r"^A.b must be an integer >= 1, got 0$"):
        require_int("A", "b", 0, 1)
    require_int("A", "b", 10**9, 1)
    with pytest.raises(ConfigError, match=r"^A.b must be an integer in \[1, 5\], got 6$"):
        require_int("A", "b", 6, 1, 5)
    with pytest.raises(ConfigError, match=r"^A.b must be a finite number > 0 m, got 0$"):
        require_positive("A", "b", 0, "m")
    require_positive("A", "b", 1e9, "m")
    with pytest.raises(ConfigError, match=r"^A.b must be in \(0, 1\] , got 2$"):
        require_range("A", "b", 2, 0.0, 1.0, "")


# -- writers and readers -----------------------------------------------------------------------

FILE_BOUNDS = [
    # (function, keyword, low, high, range text as written in the message)
    ("ros_map.write", "resolution_m", 0.01, 1.0, "[0.01, 1] m"),
    ("ros_map.write", "wall_thickness_m", 0.0, 1.0, "[0, 1] m"),
    ("ros_map.write", "margin_m", 0.0, 10.0, "[0, 10] m"),
    ("worldgen.write", "grid_m", 1.0, 10.0, "[1, 10] m"),
    ("worldgen.read", "grid_m", 1.0, 10.0, "[1, 10] m"),
    ("worldgen.read", "door_width_m", 0.6, 3.0, "[0.6, 3] m"),
    ("floorplan.read", "door_width_m", 0.6, 3.0, "[0.6, 3] m"),
]
FILE_IDS = [f"{f}.{k}" for f, k, *_ in FILE_BOUNDS]


def _call(function: str, building, tmp_path, **kwargs):
    """Run ``function`` (a writer on ``building``, a reader on a file written from it)."""
    from realistic_indoor.io import ros_map, worldgen
    from realistic_indoor.io.floorplan import reader as floorplan_reader
    from realistic_indoor.io.floorplan import writer as floorplan_writer

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", worldgen.LossyExportWarning)
        if function == "ros_map.write":
            return ros_map.write(building, tmp_path / "map.yaml", **kwargs)
        if function == "worldgen.write":
            return worldgen.write(building, tmp_path / "plan.wg.xml", **kwargs)
        if function == "worldgen.read":
            path = tmp_path / "in.wg.xml"
            if not path.exists():
                worldgen.write(building, path)
            return worldgen.read(path, **kwargs)
        path = tmp_path / "in.xml"
        if not path.exists():
            floorplan_writer.write(building, path)
        return floorplan_reader.read(path, **kwargs)


@pytest.mark.parametrize(("function", "keyword", "low", "high", "text"), FILE_BOUNDS, ids=FILE_IDS)
def test_file_options__edges_pass_and_outside_is_refused(
    tiny_office, tmp_path, function, keyword, low, high, text
):
    for value in (low, high):
        _call(function, tiny_office, tmp_path, **{keyword: value})
    owner = function.removesuffix(".write") if function == "ros_map.write" else function
    for value in (math.nextafter(low, -math.inf), math.nextafter(high, math.inf), 100 * high, math.nan, True):
        with pytest.raises(ConfigError) as info:
            _call(function, tiny_office, tmp_path, **{keyword: value})
        assert str(info.value) == f"{owner}.{keyword} must be a finite number in {text}, got {value!r}"


# -- generators ----------------------------------------------------------------------------------

AREAS = [
    ("office", 250.0, 50_000.0),
    ("school", 300.0, 50_000.0),
    ("house", 50.0, 1000.0),
    ("random", 225.0, 360_000.0),
]


@pytest.mark.parametrize(("name", "low", "high"), AREAS, ids=[a[0] for a in AREAS])
def test_generator_area__edges_pass_and_outside_is_refused(name, low, high):
    from realistic_indoor.generator import area_limits, make_generator

    assert area_limits(name) == (low, high)
    for area in (low, high):
        make_generator(name, area)
    with pytest.raises(ConfigError, match=f"the smallest is {low:g} m2"):
        make_generator(name, math.nextafter(low, 0))
    with pytest.raises(ConfigError, match=f"the largest is {high:g} m2"):
        make_generator(name, math.nextafter(high, math.inf))
    for bad in (math.nan, math.inf, True, "big"):
        with pytest.raises(ConfigError, match="area"):
            make_generator(name, bad)


# -- the command line ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (
            ["convert", "{plan}", "-o", "{tmp}/x.yaml", "--resolution", "100"],
            "--resolution must be a finite number in [0.01, 1] m, got 100.0",
        ),
        (
            ["convert", "{plan}", "-o", "{tmp}/x.yaml", "--resolution", "nan"],
            "--resolution must be a finite number in [0.01, 1] m, got nan",
        ),
        (
            ["convert", "{plan}", "-o", "{tmp}/x.sdf", "--wall-thickness", "100"],
            "--wall-thickness must be a finite number in [0.01, 1] m, got 100.0",
        ),
        (
            ["convert", "{plan}", "-o", "{tmp}/x.yaml", "--wall-thickness", "100"],
            "--wall-thickness must be a finite number in [0.01, 1] m, got 100.0",
        ),
        (
            ["convert", "{plan}", "-o", "{tmp}/x.sdf", "--wall-height", "11"],
            "--wall-height must be a finite number in [0.1, 10] m, got 11.0",
        ),
        (
            ["generate", "--seed", "1", "-o", "{tmp}/x.sdf", "--wall-thickness", "100"],
            "--wall-thickness must be a finite number in [0.01, 1] m, got 100.0",
        ),
        (
            ["generate", "--area", "1e9", "-o", "{tmp}/x.json"],
            "office area 1e+09 m2 is too large: the largest is 50000 m2",
        ),
        (["validate", "{plan}", "--worst", "-1"], "--worst must be an integer in [0, 100], got -1"),
        (["validate", "{plan}", "--worst", "101"], "--worst must be an integer in [0, 100], got 101"),
    ],
)
def test_cli__out_of_range_option_is_one_line_error_before_any_work(
    tiny_office, tmp_path, capsys, argv, message
):
    from realistic_indoor.cli import main
    from realistic_indoor.io import save

    plan = tmp_path / "plan.json"
    save(tiny_office, plan)
    code = main([a.format(plan=plan, tmp=tmp_path) for a in argv])
    err = capsys.readouterr().err.strip()
    assert code == 1
    assert len(err.splitlines()) == 1 and "Traceback" not in err, err
    assert message in err, err
    assert not list(tmp_path.glob("x.*"))


def test_cli__edges_of_the_ros_resolution_pass(tiny_office, tmp_path):
    from realistic_indoor.cli import main
    from realistic_indoor.io import save

    plan = tmp_path / "plan.json"
    save(tiny_office, plan)
    for i, resolution in enumerate(("0.01", "1")):
        assert (
            main(["convert", str(plan), "-o", str(tmp_path / f"m{i}.yaml"), "--resolution", resolution]) == 0
        )
