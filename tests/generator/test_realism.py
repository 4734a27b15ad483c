"""With the paper's model, generated offices and schools match its Table 1 for their type (200 buildings each).

Houses follow the programme table of published residential statistics instead (Table 1's houses
have a corridor for every four rooms and halls of 60 m2): see test_house_programme.py.
"""

import pytest

from realistic_indoor.building import SemanticLabel
from realistic_indoor.models import reference_table
from realistic_indoor.validator.connectivity import Connectivity, connectivity
from realistic_indoor.validator.tables import label_table

TYPES = ["office", "school"]
C, H = SemanticLabel.CORRIDOR, SemanticLabel.HALL


@pytest.fixture(scope="module")
def tables(samples):
    """``tables(kind)``: (generated table, paper table) for a type."""
    cache = {}

    def get(kind):
        if kind not in cache:
            cache[kind] = (label_table(samples(kind, "paper")), reference_table(kind))
        return cache[kind]

    return get


@pytest.mark.parametrize("kind", TYPES)
def test_realism__label_shares_within_5_points_of_table_1(kind, tables):
    got, ref = tables(kind)
    off = {lab.value: round(got[lab]["share_pct"] - ref[lab]["share_pct"], 1) for lab in SemanticLabel}
    assert all(abs(v) <= 5.0 for v in off.values()), off


@pytest.mark.parametrize("kind", TYPES)
def test_realism__doors_per_room_near_table_1(kind, tables):
    got, ref = tables(kind)
    tolerance = {C: 1.5, H: 1.5}
    off = {lab.value: round(got[lab]["doors_mean"] - ref[lab]["doors_mean"], 2) for lab in SemanticLabel}
    assert all(abs(off[lab.value]) <= tolerance.get(lab, 0.3) for lab in SemanticLabel), off


@pytest.mark.parametrize("kind", TYPES)
def test_realism__mean_area_within_25_percent_for_every_label(kind, tables):
    got, ref = tables(kind)
    off = {lab.value: round(got[lab]["area_mean"] / ref[lab]["area_mean"] - 1, 3) for lab in SemanticLabel}
    assert all(abs(v) <= 0.25 for v in off.values()), off


@pytest.mark.parametrize("kind", TYPES)
def test_realism__corridor_axes_ratio_within_2_of_table_1(kind, tables):
    got, ref = tables(kind)
    assert abs(got[C]["axes_ratio_mean"] - ref[C]["axes_ratio_mean"]) <= 2.0


@pytest.fixture(scope="module")
def office_connectivity(samples):
    return Connectivity.combine([connectivity(b) for b in samples("office", "paper")])


def test_office__offices_touch_a_corridor(office_connectivity):
    assert office_connectivity.core_touching_corridor_pct >= 95.0


def test_office__most_rooms_connect_only_to_corridors(office_connectivity):
    assert 60.0 <= office_connectivity.only_to_corridors_pct <= 80.0
