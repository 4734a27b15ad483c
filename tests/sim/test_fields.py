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


@pytest.mark.parametrize("share", [0.0005, 0.01, 0.3, 0.9, 1.0])
def test_distance_field__equals_scipys_distances_to_the_last_bit(rng, share):
    obstacle = rng.random((97, 131)) < share
    obstacle[40:60, :] = False  # a band free across the whole width: no obstacle in its rows
    want = distance_transform_edt(~obstacle).astype(np.float32)
    assert np.array_equal(distance_field(obstacle), want)


def test_distance_field__one_obstacle_cell_in_one_column_only():
    obstacle = np.zeros((40, 7), dtype=bool)
    obstacle[39, 6] = True  # every other column has none: its squares are 1e20
    want = distance_transform_edt(~obstacle).astype(np.float32)
    assert np.array_equal(distance_field(obstacle), want)


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


def test_distance_field__level_runs_and_envelope_runs_agree_with_scipy():
    obstacle = np.ones((30, 200), dtype=bool)
    obstacle[3:27, 1:199] = False  # one room: level runs in its middle rows
    obstacle[3:27, 100] = True  # a wall across it, with a door
    obstacle[12:15, 100] = False
    obstacle[0:3, 40:43] = False  # a door in the top wall to the grid's edge: uneven runs
    want = distance_transform_edt(~obstacle).astype(np.float32)
    assert np.array_equal(distance_field(obstacle), want)


def test_distance_field__refuses_grids_too_wide_for_exact_integers():
    from realistic_indoor.sim._edt import MAX_WIDTH

    with pytest.raises(ValueError, match="cells wide"):
        distance_field(np.zeros((1, MAX_WIDTH + 1), dtype=bool))


def test_distance_field__rows_of_many_stretches_agree_with_scipy():
    obstacle = np.ones((40, 300), dtype=bool)
    obstacle[2:38, 1:299] = False
    obstacle[2:20, 10:290:12] = True  # a comb of short walls: runs of 3 stretches below them
    obstacle[20:38, 5:295:7] = True  # and of dozens of stretches across them
    obstacle[25:28, 5:295:7] = False  # doors through the comb
    want = distance_transform_edt(~obstacle).astype(np.float32)
    assert np.array_equal(distance_field(obstacle), want)


@pytest.mark.parametrize("width", [60, 250, 900])
def test_distance_field__a_skyline_of_random_steps_agrees_with_scipy(rng, width):
    # walls hang from the top to random depths in steps of random widths: below them each row's
    # column distances form stretches of random levels, a deep one often between two shallow
    # ones (never nearest), up to a few dozen per run (solved by stretch) or a hundred (by point)
    obstacle = np.zeros((80, width), dtype=bool)
    obstacle[:, 0] = obstacle[:, -1] = True
    c = 1
    while c < width - 1:
        step = int(rng.integers(1, 13))
        obstacle[: int(rng.integers(0, 40)), c : c + step] = True
        c += step
    want = distance_transform_edt(~obstacle).astype(np.float32)
    assert np.array_equal(distance_field(obstacle), want)
