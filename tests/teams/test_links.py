"""Radio links: the walls between two points and each model's verdict, worked out by hand."""

from __future__ import annotations

import math

import numpy as np
import pytest
from team_buildings import centre, rooms_in_a_row

from realistic_indoor.errors import ConfigError
from realistic_indoor.sim import World
from realistic_indoor.teams.links import (
    COMM_MODELS,
    LineOfSightLinks,
    NoLinks,
    RangeLinks,
    UnlimitedLinks,
    WssLinks,
    as_link_model,
    connected,
    walls_crossed,
)


@pytest.fixture(scope="module")
def world():
    return World(rooms_in_a_row(4))


def test_walls_crossed__counts_each_wall_between_rooms_once(world):
    xy = np.array([centre(0), centre(1), centre(3), (2.0, 5.0), (14.0, 5.0)])  # rooms 0, 1, 3; corridor
    walls = walls_crossed(world, xy)
    assert walls[0, 1] == 1 and walls[0, 2] == 3 and walls[1, 2] == 2
    assert walls[3, 4] == 0  # along the corridor
    assert walls[0, 3] == 0  # room 0's centre to the corridor through its door (x = 2)
    assert walls[2, 3] == 2  # room 3 to (2, 5): the walls at x = 12 and 8, then out through room 1's door
    assert (walls == walls.T).all() and (np.diag(walls) == 0).all()


def test_wss__link_budget_worked_out_by_hand(world):
    """Rooms 0 and 3: 12 m, three walls. Default: -20 - 20 log10(12) - 3 x 6.3 = -60.48 dBm."""
    xy = np.array([centre(0), centre(3)])
    model = WssLinks()
    assert model.signal_dbm(world, xy)[0, 1] == pytest.approx(-20 - 20 * math.log10(12) - 3 * 6.3)
    assert model.linked(world, xy)[0, 1]
    lossy = WssLinks(wall_loss_db=20.0)  # -20 - 21.58 - 60 = -101.6 < -93: dropped
    assert lossy.signal_dbm(world, xy)[0, 1] == pytest.approx(-101.58, abs=0.01)
    assert not lossy.linked(world, xy)[0, 1]
    two = np.array([centre(0), centre(2)])  # 8 m, two walls: -20 - 18.06 - 40 = -78.06 >= -93
    assert lossy.linked(world, two)[0, 1]
    capped = WssLinks(wall_loss_db=20.0, max_walls=2)  # the third wall is not counted
    assert capped.signal_dbm(world, xy)[0, 1] == pytest.approx(-20 - 20 * math.log10(12) - 40)


def test_wss_competition__settings_and_range():
    c = WssLinks.competition()
    assert (c.p_d0_dbm, c.d0_m, c.exponent, c.wall_loss_db, c.max_walls, c.cutoff_dbm) == (
        -49.5, 2.0, 1.0, 6.3, 5, -93.0,
    )  # fmt: skip
    # behind five walls (capped): -49.5 - 10 log10(d / 2) - 31.5 = -93 at d = 2 x 10^1.2 m
    assert c.range_through_m(7) == pytest.approx(2 * 10**1.2)
    assert WssLinks(wall_loss_db=50.0).range_through_m(2) == 0.0


def test_range_los_unlimited_none(world):
    xy = np.array([centre(0), centre(1), (2.0, 5.0)])  # rooms 0 and 1 (4 m, one wall), corridor
    assert RangeLinks(range_m=4.0).linked(world, xy)[0, 1]
    assert not RangeLinks(range_m=3.9).linked(world, xy)[0, 1]
    los = LineOfSightLinks().linked(world, xy)
    assert not los[0, 1] and los[0, 2]  # the wall between rooms; room 0's door to the corridor
    assert UnlimitedLinks().linked(world, xy).sum() == 6 and NoLinks().linked(world, xy).sum() == 0


def test_connected__joins_chains_of_links():
    links = np.zeros((5, 5), dtype=bool)
    for a, b in ((0, 1), (1, 2), (3, 4)):
        links[a, b] = links[b, a] = True
    assert connected(links).tolist() == [0, 0, 0, 1, 1]


def test_link_models__refuse_bad_settings():
    assert {as_link_model(name).name for name in COMM_MODELS} == set(COMM_MODELS)
    for bad in (lambda: as_link_model("radio"), lambda: WssLinks(cutoff_dbm=10.0), lambda: RangeLinks(-1.0)):
        with pytest.raises(ConfigError) as e:
            bad()
        assert "\n" not in str(e.value)
