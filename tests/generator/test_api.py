import pickle

import numpy as np
import pytest

from realistic_indoor.errors import ConfigError
from realistic_indoor.generator import (
    GENERATOR_NAMES,
    Generator,
    OfficeGenerator,
    generate,
    make_generator,
)
from realistic_indoor.io.json_format import dumps

TYPES = ["office", "school", "house"]


@pytest.mark.parametrize("kind", TYPES)
def test_generate__same_seed_gives_identical_json(kind):
    assert dumps(generate(kind, seed=11)) == dumps(generate(kind, seed=11))


@pytest.mark.parametrize("kind", TYPES)
def test_generate__different_seeds_differ(kind):
    assert dumps(generate(kind, seed=1)) != dumps(generate(kind, seed=2))


@pytest.mark.parametrize("kind", TYPES)
def test_generate__metadata_names_generator_params_and_seed(kind):
    b = generate(kind, seed=5)
    assert b.metadata["generator"] == kind
    assert b.metadata["seed"] == 5
    assert "area_m2" in b.metadata["params"]
    assert b.building_type.value == kind


def test_generate__without_seed_records_the_one_drawn():
    b = generate("office", area_m2=600)
    again = generate("office", area_m2=600, seed=b.metadata["seed"])
    assert dumps(again) == dumps(b)


@pytest.mark.parametrize("kind", TYPES)
def test_generator__pickles_and_draws_the_same_building(kind):
    gen = make_generator(kind)
    copy = pickle.loads(pickle.dumps(gen))
    assert copy == gen
    assert isinstance(copy, Generator)
    one = gen(np.random.default_rng(3))
    two = copy(np.random.default_rng(3))
    assert dumps(one) == dumps(two)


def test_generator__consumes_the_rng_passed_in():
    gen = OfficeGenerator(area_m2=800)
    rng = np.random.default_rng(9)
    first, second = gen(rng), gen(rng)
    assert dumps(first) != dumps(second)


def test_generator__area_comes_out_as_asked():
    for area in (300, 1500, 4000):
        b = OfficeGenerator(area_m2=area)(np.random.default_rng(0))
        assert b.area == pytest.approx(area, rel=0.03)


def test_make_generator__unknown_type_lists_valid_ones():
    with pytest.raises(ConfigError, match=", ".join(GENERATOR_NAMES)):
        make_generator("castle")


@pytest.mark.parametrize("area", [-5, 0, float("nan"), float("inf"), "big"])
def test_make_generator__rejects_nonsense_areas(area):
    with pytest.raises(ConfigError, match="area"):
        make_generator("office", area)


def test_make_generator__too_small_area_names_the_minimum():
    with pytest.raises(ConfigError, match="smallest is 250 m2"):
        make_generator("office", 100)


def test_make_generator__absurd_area_names_the_maximum():
    with pytest.raises(ConfigError, match="largest is 50000 m2"):
        make_generator("office", 1e7)


def test_make_generator__unknown_option_is_a_config_error():
    with pytest.raises(ConfigError, match="bad option"):
        make_generator("office", 1000, floors=3)


@pytest.mark.parametrize("seed", [-1, 1.5, "7"])
def test_generate__rejects_bad_seeds(seed):
    with pytest.raises(ConfigError, match="seed"):
        generate("office", 500, seed=seed)


def test_make_generator__a_house_has_its_own_limits():
    with pytest.raises(ConfigError, match="smallest is 50 m2"):
        make_generator("house", 20)
    with pytest.raises(ConfigError, match="largest is 1000 m2"):
        make_generator("house", 10_000)
