import numpy as np
import pytest
from scipy.ndimage import distance_transform_edt

from realistic_indoor.errors import ConfigError
from realistic_indoor.sim.fields import distance_field


def test_distance_field__is_the_exact_euclidean_distance_transform(rng):
    noise = rng.random((123, 77)) < 0.02
    dist = distance_field(noise)
    assert dist.dtype == np.float32 and dist.shape == noise.shape
    assert np.abs(dist - distance_transform_edt(~noise)).max() < 1e-4


def test_distance_field__scales_cells_to_metres():
    obstacle = np.zeros((5, 9), dtype=bool)
    obstacle[2, 0] = True
    in_cells = distance_field(obstacle)
    assert in_cells[2, 8] == pytest.approx(8.0) and in_cells[0, 0] == pytest.approx(2.0)
    assert np.array_equal(distance_field(obstacle, 0.1), in_cells * np.float32(0.1))


def test_distance_field__without_obstacles_is_huge_and_needs_a_positive_resolution():
    assert np.all(distance_field(np.zeros((3, 4), dtype=bool), 0.5) == np.float32(0.5e10))
    with pytest.raises(ConfigError, match="resolution_m"):
        distance_field(np.zeros((3, 4), dtype=bool), 0.0)
