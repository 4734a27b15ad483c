import json
import pickle

import numpy as np
import pytest

from realistic_indoor.building import SemanticLabel
from realistic_indoor.errors import ConfigError
from realistic_indoor.models import BuildingTypeModel, default_model, real_model, reference_table


@pytest.mark.parametrize("kind", ["office", "school", "house"])
def test_default_model__carries_table_1_of_the_paper(kind):
    model, table = default_model(kind), reference_table(kind)
    for lab in SemanticLabel:
        assert model.stats(lab).area_mean == table[lab]["area_mean"]
        assert model.shares()[lab] * 100 == pytest.approx(table[lab]["share_pct"], abs=0.2)
        assert model.table()[lab]["doors_mean"] == table[lab]["doors_mean"]


@pytest.mark.parametrize("kind", ["office", "school", "house"])
def test_default_model__mixes_are_distributions_over_known_labels(kind):
    model = default_model(kind)
    for lab in SemanticLabel:
        assert sum(model.connections[lab].values()) == pytest.approx(1.0, abs=1e-6)
        assert set(model.connections[lab]) <= {*(x.value for x in SemanticLabel), "outside"}
        assert model.function_weights(lab)


def test_default_model__offices_are_mostly_offices():
    weights = default_model("office").function_weights(SemanticLabel.MEDIUM)
    assert max(weights, key=weights.get) == "office"


def test_default_model__unknown_type_lists_valid_ones():
    with pytest.raises(ConfigError, match="office, school, house"):
        default_model("castle")


def test_model__round_trips_through_json_and_pickle():
    model = default_model("school")
    again = BuildingTypeModel.from_dict(json.loads(json.dumps(model.to_dict())))
    assert again == model
    assert pickle.loads(pickle.dumps(model)) == model


def test_model__malformed_dict_is_a_config_error():
    with pytest.raises(ConfigError, match="malformed"):
        BuildingTypeModel.from_dict({"name": "x"})


def test_model__missing_label_is_a_config_error():
    model = default_model("office")
    labels = {k: v for k, v in model.labels.items() if k is not SemanticLabel.HALL}
    with pytest.raises(ConfigError, match="hall"):
        BuildingTypeModel("x", labels, model.connections, model.functions)


def test_label_stats__areas_follow_the_mean_and_spread():
    stats = default_model("office").stats("medium")
    rng = np.random.default_rng(0)
    draws = np.array([stats.sample_area(rng) for _ in range(20_000)])
    assert draws.mean() == pytest.approx(stats.area_mean, rel=0.05)
    assert draws.std() == pytest.approx(stats.area_std, rel=0.15)
    assert (draws > 0).all()


def test_paper_model__has_no_size_scaling():
    """Table 1 gives one mean area per label: the paper's model keeps it at every size."""
    model = default_model("school")
    assert model.at_area(300.0) is model and model.at_area(30000.0) is model


def test_real_school_model__grows_its_rooms_with_the_floor_area():
    model = real_model("school")
    small, large = model.at_area(800.0), model.at_area(8000.0)
    assert small.stats("medium").area_mean < model.stats("medium").area_mean < large.stats("medium").area_mean
