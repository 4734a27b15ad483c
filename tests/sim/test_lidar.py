import math

import numpy as np
import pytest
from numba.typed import List

from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.lidar import Lidar, LidarConfig, beam_offsets, draw_noise
from realistic_indoor.sim.raster import RASTER_OUTSIDE, RASTER_WALL, rasterize
from realistic_indoor.sim.raycast import Raycaster


@pytest.fixture
def tiny_raycaster(tiny_office):
    return Raycaster(rasterize(tiny_office))


def test_lidar__beams_span_the_field_of_view_about_the_heading():
    lidar = Lidar(LidarConfig(fov_rad=math.radians(270), n_beams=109))
    assert lidar.offsets_rad[0] == pytest.approx(-math.radians(135))
    assert lidar.offsets_rad[-1] == pytest.approx(math.radians(135))
    assert lidar.offsets_rad[54] == pytest.approx(0.0)
    assert np.diff(lidar.offsets_rad) == pytest.approx(np.full(108, math.radians(2.5)))


def test_lidar__full_circle_has_no_duplicate_beam():
    offsets = Lidar(LidarConfig(fov_rad=2 * math.pi, n_beams=8)).offsets_rad
    assert np.diff(offsets) == pytest.approx(np.full(7, math.pi / 4))
    assert offsets[-1] - offsets[0] == pytest.approx(2 * math.pi - math.pi / 4)


def test_beam_offsets__are_the_scanners_beams_and_a_new_array():
    config = LidarConfig(fov_rad=math.radians(180), n_beams=7)
    lidar = Lidar(config)
    offsets = beam_offsets(config)
    assert np.array_equal(offsets, lidar.offsets_rad) and offsets is not lidar.offsets_rad
    assert offsets.flags.writeable and not lidar.offsets_rad.flags.writeable
    assert np.array_equal(beam_offsets(LidarConfig(n_beams=1)), [0.0])


def test_lidar__readings_turn_with_the_heading(tiny_raycaster):
    lidar = Lidar(LidarConfig(fov_rad=math.pi, n_beams=3, noise_std_m=0.0))
    # in room a (0..5 x 2..6), at (2, 4) facing north: beams point east, north, west
    scan = lidar.scan(tiny_raycaster, (2.0, 4.0, math.pi / 2))
    assert scan.ranges_m == pytest.approx([2.95, 1.95, 1.95], abs=1e-4)
    assert scan.returned.all()


def test_lidar__no_return_reads_max_range(tiny_raycaster):
    lidar = Lidar(LidarConfig(fov_rad=math.pi / 2, n_beams=2, max_range_m=1.0, noise_std_m=0.5))
    scan = lidar.scan(tiny_raycaster, (2.0, 4.0, 0.0), np.random.default_rng(0))
    assert (scan.ranges_m == 1.0).all() and not scan.returned.any()


def test_lidar__beam_through_the_entrance_reads_max_range(tiny_raycaster):
    lidar = Lidar(LidarConfig(fov_rad=0.1, n_beams=1, max_range_m=10.0))
    scan = lidar.scan(tiny_raycaster, (3.0, 1.0, math.pi), np.random.default_rng(0))
    assert scan.ranges_m[0] == 10.0
    assert scan.true.kind[0] == RASTER_OUTSIDE and scan.true.range_m[0] == pytest.approx(3.0, abs=0.05)


def test_lidar__noise_is_gaussian_with_the_configured_spread(tiny_raycaster):
    lidar = Lidar(LidarConfig(fov_rad=0.01, n_beams=2, noise_std_m=0.02))
    rng = np.random.default_rng(7)
    readings = np.concatenate(
        [lidar.scan(tiny_raycaster, (2.0, 4.0, 0.0), rng).ranges_m for _ in range(2000)]
    )
    assert readings.mean() == pytest.approx(2.95, abs=0.002)
    assert readings.std() == pytest.approx(0.02, rel=0.1)


def test_lidar__same_rng_seed_gives_the_same_scan(tiny_raycaster):
    lidar = Lidar()
    a = lidar.scan(tiny_raycaster, (2.0, 4.0, 0.3), np.random.default_rng(3))
    b = lidar.scan(tiny_raycaster, (2.0, 4.0, 0.3), np.random.default_rng(3))
    assert a.ranges_m.tobytes() == b.ranges_m.tobytes()
    assert a.ranges_m.dtype == np.float32 and (a.true.kind == RASTER_WALL).any()


@pytest.mark.parametrize(
    "kwargs",
    [
        {"n_beams": 0},
        {"n_beams": 2.5},
        {"max_range_m": -1.0},
        {"max_range_m": 0.0},
        {"noise_std_m": -0.1},
        {"fov_rad": 0.0},
        {"fov_rad": 7.0},
    ],
)
def test_lidar_config__bad_values_raise_config_error(kwargs):
    with pytest.raises(ConfigError, match="LidarConfig"):
        LidarConfig(**kwargs)


def test_draw_noise__chosen_rows_get_each_generators_own_normal_draws():
    out = np.full((3, 5), 9.0)
    draw_noise(List([np.random.default_rng(s) for s in (1, 2, 3)]), np.array([True, False, True]), out)
    # the same draws NumPy makes from generators seeded alike; the row not chosen is untouched
    assert out[0].tolist() == np.random.default_rng(1).standard_normal(5).tolist()
    assert out[1].tolist() == [9.0] * 5
    assert out[2].tolist() == np.random.default_rng(3).standard_normal(5).tolist()


def test_draw_noise__advances_the_generators_a_python_caller_holds():
    generators = [np.random.default_rng(4), np.random.default_rng(5)]
    draw_noise(List(generators), np.array([True, True]), np.empty((2, 3)))
    expected = np.random.default_rng(4)
    expected.standard_normal(3)
    assert generators[0].random() == expected.random()  # the next value after the three drawn
