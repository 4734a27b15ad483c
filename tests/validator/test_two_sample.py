import pytest

from realistic_indoor.errors import ConfigError
from realistic_indoor.validator.two_sample import (
    FEATURE_NAMES,
    building_features,
    split_half_accuracy,
    two_sample_test,
)


def test_building_features__one_value_per_name_and_no_nan(maze_office):
    v = building_features(maze_office)
    assert v.shape == (len(FEATURE_NAMES),)
    named = dict(zip(FEATURE_NAMES, v, strict=True))
    assert named["corridor share"] == pytest.approx(0.25)
    assert named["corridor doorways"] == pytest.approx(3.5)
    assert named["hall doorways"] == 0.0
    assert named["core rooms touching a corridor"] == pytest.approx(0.6)


def test_two_sample_test__identical_sets_are_indistinguishable(maze_office):
    r = two_sample_test([maze_office] * 6, [maze_office] * 6, names=("a", "b"))
    assert r.accuracy == pytest.approx(0.5)
    assert r.telling_features == ()


def test_two_sample_test__different_structures_are_separable(maze_office, tiny_office, scaled):
    a = [scaled(maze_office, f) for f in (0.9, 1.0, 1.1, 1.2, 1.3)]
    b = [scaled(tiny_office, f) for f in (0.9, 1.0, 1.1, 1.2, 1.3, 1.4)]
    r = two_sample_test(a, b, names=("maze", "tiny"), seed=3)
    assert r.accuracy == pytest.approx(1.0)
    assert (r.n_a, r.n_b, r.folds) == (5, 6, 100)  # 5 folds x 20 repeats
    assert r.sentence().startswith("maze vs tiny: balanced accuracy 1.00")


def test_two_sample_test__deterministic_given_the_seed(maze_office, tiny_office, scaled):
    a = [scaled(maze_office, f) for f in (0.5, 1.0, 2.0)] + [tiny_office]
    b = [scaled(tiny_office, f) for f in (0.5, 1.0, 2.0)] + [maze_office]
    assert two_sample_test(a, b, seed=1) == two_sample_test(a, b, seed=1)


def test_two_sample_test__needs_two_buildings_per_set(maze_office):
    with pytest.raises(ConfigError, match="at least 2 buildings per set; 'x' has 1"):
        two_sample_test([maze_office], [maze_office] * 3, names=("x", "y"))


def test_two_sample_test__scale_alone_is_invisible_unless_areas_are_asked_for(maze_office, scaled):
    small = [scaled(maze_office, f) for f in (0.9, 1.0, 1.1, 1.2)]
    large = [scaled(maze_office, 3 * f) for f in (0.9, 1.0, 1.1, 1.2)]
    assert two_sample_test(small, large).accuracy == pytest.approx(0.5)
    with_area = two_sample_test(small, large, with_area=True)
    assert with_area.accuracy == pytest.approx(1.0)
    assert all("log area" in name for name, _coef in with_area.telling_features)


def test_split_half_accuracy__one_population_cut_in_halves_is_near_chance(maze_office, tiny_office, scaled):
    # 12 buildings, six of each structure: random halves mix both, so no rule learnt on one
    # half's labels carries over to the held-out folds better than chance on average
    plans = [scaled(maze_office, f) for f in (0.8, 0.9, 1.0, 1.1, 1.2, 1.3)]
    plans += [scaled(tiny_office, f) for f in (0.8, 0.9, 1.0, 1.1, 1.2, 1.3)]
    mean, spread = split_half_accuracy(plans, features="room", splits=10)
    assert 0.3 < mean < 0.65
    assert spread > 0  # the halvings differ


def test_split_half_accuracy__needs_four_buildings(maze_office):
    with pytest.raises(ConfigError, match="at least 4 buildings; the set has 3"):
        split_half_accuracy([maze_office] * 3)


def test_building_features__the_probe_keeps_the_room_density(maze_office, scaled):
    # the building level always carries rooms per hectare: the same plan at twice the length
    # has a quarter of the density, so the two sets are told apart
    small = [scaled(maze_office, f) for f in (0.9, 1.0, 1.1, 1.2)]
    large = [scaled(maze_office, 2 * f) for f in (0.9, 1.0, 1.1, 1.2)]
    r = two_sample_test(small, large, features="building")
    assert r.accuracy == pytest.approx(1.0)
    assert r.telling_features[0][0] == "log rooms per hectare"
