import math

import pytest

from realistic_indoor.building import Building, Door, Room, SemanticLabel, check_building
from realistic_indoor.building.check import InvalidBuildingError
from realistic_indoor.errors import ConfigError


def test_room__area_and_axes_ratio_in_metres():
    r = Room.rectangle("r", "medium", "office", (0, 0, 6, 3))
    assert r.area == pytest.approx(18.0)
    assert r.axes_ratio == pytest.approx(2.0)
    assert r.label is SemanticLabel.MEDIUM


def test_room__outline_normalised_counter_clockwise_without_closing_point():
    r = Room("r", "small", "storage", [(0, 0), (0, 2), (2, 2), (2, 0), (0, 0)])
    assert len(r.outline) == 4
    assert r.polygon.exterior.is_ccw


def test_labels__unknown_label_lists_valid_ones():
    with pytest.raises(ConfigError, match="corridor, hall, small, medium, big"):
        Room.rectangle("r", "huge", "office", (0, 0, 1, 1))


def test_building__unknown_type_lists_valid_ones():
    with pytest.raises(ConfigError, match="office, school, house"):
        Building("castle", ())


def test_check__valid_building_has_no_findings(tiny_office):
    assert check_building(tiny_office) == []


def test_check__reports_every_violation():
    rooms = (
        Room.rectangle("c", "corridor", "corridor", (0, 0, 10, 2)),
        Room.rectangle("a", "medium", "office", (0, 2, 5, 6)),
        Room.rectangle("x", "small", "storage", (1, 1, 3, 3)),
        Room.rectangle("far", "small", "storage", (20, 20, 22, 22)),
    )
    doors = (
        Door("d1", "a", "c", 2.5, 2.0, 0.9, 0.0),
        Door("d2", "a", "c", 3.0, 4.0, 0.9, 0.0),
        Door("d3", "a", "c", 4.0, 2.0, 0.4, 0.0),
    )
    codes = {f.code for f in check_building(Building("office", rooms, doors))}
    assert {"overlap", "door_off_wall", "narrow_door", "disconnected", "no_entrance"} <= codes


def test_check__unreachable_rooms_named():
    rooms = (
        Room.rectangle("c", "corridor", "corridor", (0, 0, 10, 2)),
        Room.rectangle("a", "medium", "office", (0, 2, 5, 6)),
    )
    b = Building("office", rooms, (Door("e", "c", None, 0.0, 1.0, 1.0, math.pi / 2),))
    (finding,) = [f for f in check_building(b) if f.code == "unreachable"]
    assert finding.ids == ("a",)


def test_check__raise_on_error_carries_findings():
    b = Building("office", (Room.rectangle("a", "medium", "office", (0, 0, 4, 4)),))
    with pytest.raises(InvalidBuildingError) as e:
        check_building(b, raise_on_error=True)
    assert e.value.findings[0].code == "no_entrance"


def test_graph__node_per_room_edge_per_door(tiny_office):
    g = tiny_office.graph()
    assert set(g.nodes) == {"c", "a", "b"}
    assert g.number_of_edges() == 2
    assert g.nodes["a"]["label"] is SemanticLabel.MEDIUM
    assert tiny_office.graph(include_outside=True).number_of_edges() == 3


def test_walls__shared_walls_once_and_gaps_at_doors(tiny_office):
    from shapely.geometry import LineString, MultiLineString, Point

    walls = MultiLineString([LineString(s) for s in tiny_office.walls])
    # total outline length: perimeter 32 m + interior walls 10 + 4 m, minus 3 doors (0.9, 0.9, 1.2)
    assert walls.length == pytest.approx(32 + 10 + 4 - 0.9 - 0.9 - 1.2)
    for d in tiny_office.doors:
        assert walls.distance(Point(d.x, d.y)) > 0.4
