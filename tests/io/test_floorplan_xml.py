import json
import math
import xml.etree.ElementTree as ET

import pytest

from realistic_indoor.building import BuildingType, SemanticLabel
from realistic_indoor.errors import ConfigError, PlanFormatError
from realistic_indoor.io import load, save
from realistic_indoor.io.floorplan_xml import read, write
from realistic_indoor.io.function_labels import load_label_map, semantic_label_for

# A plan in pixels, y down, 10 px = 50 cm (0.05 m/px): office A (200 x 100 px = 10 m x 5 m) left
# of corridor B (100 x 100 px), joined by a zero-length portal at (300, 150) on their shared wall.
A_RING = [(100, 100), (300, 100), (300, 200), (100, 200)]
B_RING = [(300, 100), (400, 100), (400, 200), (300, 200)]


def _space(sid, label, ring, segments=(), portals=(), closed=True):
    pts = "".join(f'<point x="{x}" y="{y}"/>' for x, y in [*ring, *ring[:1]] if closed or (x, y) != ring[0])
    segs = "".join(
        f'<linesegment id="{i}"><point x="{p[0]}" y="{p[1]}"/><point x="{q[0]}" y="{q[1]}"/>'
        f"<class>PORTAL</class><type>IMPLICIT</type></linesegment>"
        for i, p, q in segments
    )
    ports = "".join(
        f"<portal><linesegment>{i}</linesegment><class>HORIZONTAL</class><type>EXPLICIT</type>"
        f"<direction>BOTH</direction><target>{''.join(f'<id>{t}</id>' for t in targets)}</target></portal>"
        for i, targets in portals
    )
    return (
        f'<space id="{sid}"><labels><type>R</type><label>{label}</label></labels>'
        f"<bounding_polygon>{pts}</bounding_polygon>"
        f"<space_representation>{segs}</space_representation><portals>{ports}</portals></space>"
    )


def _plan(
    spaces, scale="<value>10</value><um>pixel</um>", real="<value>50</value><um>cm</um>", kind="OFFICE"
):
    scale_xml = (
        f"<scale><represented_distance>{scale}</represented_distance>"
        f"<real_distance>{real}</real_distance></scale>"
        if scale is not None
        else ""
    )
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n<building id="b-1"><name>C:\\plans\\tiny plan</name>'
        f"{scale_xml}<building_type><main_type>{kind}</main_type></building_type>"
        f"<floor><spaces>{''.join(spaces)}</spaces></floor></building>"
    )


def _two_rooms(
    a_segment=((300, 150), (300, 150)), b_segment=None, a_label="OFFICE", portal_targets=("A", "B")
):
    b_segment = a_segment if b_segment is None else b_segment
    return [
        _space("A", a_label, A_RING, [("p1", *a_segment)], [("p1", portal_targets)]),
        _space("B", "CORRIDOR", B_RING, [("p1", *b_segment)], [("p1", portal_targets)]),
    ]


@pytest.fixture
def write_plan(tmp_path):
    def _write(text, name="plan.xml"):
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        return path

    return _write


def _assert_one_line_error(excinfo, *parts):
    message = str(excinfo.value)
    assert "\n" not in message
    for part in parts:
        assert part in message, f"{part!r} not in {message!r}"


# -- reading --------------------------------------------------------------------------------


def test_read__scales_to_metres_flips_y_and_moves_to_origin(write_plan):
    b = read(write_plan(_plan(_two_rooms())))
    a, c = b.room("A"), b.room("B")
    assert a.bounds == pytest.approx((0, 0, 10, 5))
    assert c.bounds == pytest.approx((10, 0, 15, 5))
    assert a.area == pytest.approx(50.0)
    assert (a.label, a.function) == (SemanticLabel.MEDIUM, "office")
    assert (c.label, c.function) == (SemanticLabel.CORRIDOR, "corridor")
    assert b.building_type is BuildingType.OFFICE
    assert b.metadata["scale_m_per_px"] == pytest.approx(0.05)
    assert b.metadata["name"] == "tiny plan"
    assert b.metadata["building_id"] == "b-1"


def test_read__y_grows_upwards(write_plan):
    # Room A is drawn above room B on screen (smaller pixel y): in the plan it must be above.
    spaces = [
        _space("A", "OFFICE", [(0, 0), (100, 0), (100, 50), (0, 50)]),
        _space("B", "OFFICE", [(0, 50), (100, 50), (100, 100), (0, 100)]),
    ]
    b = read(write_plan(_plan(spaces)))
    assert b.room("A").bounds[1] == pytest.approx(b.room("B").bounds[3])


def test_read__zero_length_portal_is_a_default_width_door_along_the_wall(write_plan):
    b = read(write_plan(_plan(_two_rooms())), door_width_m=0.8)
    (door,) = b.doors
    assert door.id == "p1"
    assert set(door.rooms) == {"A", "B"}
    assert (door.x, door.y) == pytest.approx((10.0, 2.5))
    assert door.width_m == pytest.approx(0.8)
    assert door.angle_rad == pytest.approx(math.pi / 2)
    assert b.metadata["door_geometry"]["point"] == 1
    assert not b.validate(require_entrance=False)


def test_read__portal_listed_by_both_spaces_is_one_door(write_plan):
    b = read(write_plan(_plan(_two_rooms())))
    assert len(b.doors) == 1


def test_read__two_copies_a_door_width_apart_are_the_jambs(write_plan):
    # 18 px = 0.9 m apart along the wall x = 300: the door spans them.
    b = read(write_plan(_plan(_two_rooms(((300, 130), (300, 130)), ((300, 148), (300, 148))))))
    (door,) = b.doors
    assert door.width_m == pytest.approx(0.9)
    assert (door.x, door.y) == pytest.approx((10.0, 5 - 139 * 0.05 + 100 * 0.05))
    assert b.metadata["door_geometry"]["jambs"] == 1


def test_read__segment_with_length_gives_width_and_angle(write_plan):
    b = read(write_plan(_plan(_two_rooms(((300, 140), (300, 160))))))
    (door,) = b.doors
    assert door.width_m == pytest.approx(1.0)
    assert door.angle_rad == pytest.approx(math.pi / 2)
    assert (door.x, door.y) == pytest.approx((10.0, 2.5))


def test_read__portal_without_segment_is_placed_on_the_shared_wall(write_plan):
    spaces = [
        _space("A", "OFFICE", A_RING, [], [("gone", ("A", "B"))]),
        _space("B", "CORRIDOR", B_RING, [], [("gone", ("A", "B"))]),
    ]
    b = read(write_plan(_plan(spaces)))
    (door,) = b.doors
    assert (door.x, door.y) == pytest.approx((10.0, 2.5))
    assert door.angle_rad == pytest.approx(math.pi / 2)
    (repair,) = b.metadata["repairs"]
    assert repair["element"] == 'portal linesegment="gone"' and "placed" in repair["action"]


@pytest.mark.parametrize(
    ("unit", "value", "m_per_px"),
    [("cm", "50", 0.05), ("m", "0.5", 0.05), ("mm", "500", 0.05), ("ft", "1", 0.03048), ("in", "10", 0.0254)],
)
def test_read__scale_units(write_plan, unit, value, m_per_px):
    b = read(write_plan(_plan(_two_rooms(), real=f"<value>{value}</value><um>{unit}</um>")))
    assert b.metadata["scale_m_per_px"] == pytest.approx(m_per_px)
    assert b.room("A").area == pytest.approx(200 * 100 * m_per_px**2)


def test_read__spike_in_outline_is_dropped_and_reported(write_plan):
    # A zero-area spike out of the top wall and back makes the ring self-intersecting.
    ring = [(100, 100), (200, 100), (200, 60), (200, 100), (300, 100), (300, 200), (100, 200)]
    b = read(write_plan(_plan([_space("A", "OFFICE", ring)])))
    assert b.room("A").area == pytest.approx(50.0)
    assert len(b.room("A").outline) == 4
    (repair,) = b.metadata["repairs"]
    assert repair["element"] == 'space id="A"' and "spike" in repair["action"]


def test_read__crossing_outline_with_a_sliver_keeps_the_room_and_reports_the_loss(write_plan):
    ring = [(100, 100), (100, 200), (300, 200), (300, 102), (290, 102), (95, 102), (100, 100)]
    b = read(write_plan(_plan([_space("A", "OFFICE", ring)])))
    assert b.room("A").polygon.is_valid
    assert b.room("A").area == pytest.approx(200 * 98 * 0.0025)
    (repair,) = b.metadata["repairs"]
    assert "dropped 1 slivers" in repair["action"]


def test_read__empty_space_without_portals_is_dropped_and_reported(write_plan):
    spaces = [*_two_rooms(), _space("ghost", "CANTEEN", [(5, 5), (5, 5), (5, 5)])]
    b = read(write_plan(_plan(spaces)))
    assert [r.id for r in b.rooms] == ["A", "B"]
    assert b.metadata["repairs"][0]["element"] == 'space id="ghost"'


def test_read__groups_kept_in_metadata(write_plan):
    text = _plan(_two_rooms()).replace(
        "</floor>",
        "<groups><group_features><name>office</name><type>functional_area</type>"
        "<space>A</space></group_features></groups></floor>",
    )
    b = read(write_plan(text))
    assert b.metadata["groups"] == [{"name": "office", "type": "functional_area", "rooms": ["A"]}]


def test_read__other_building_types(write_plan):
    assert read(write_plan(_plan(_two_rooms(), kind="SCHOOL"))).building_type is BuildingType.SCHOOL
    assert read(write_plan(_plan(_two_rooms(), kind="HOSPITAL"))).building_type is BuildingType.UNKNOWN


def test_load__xml_ending_reads_floor_plans(write_plan):
    assert len(load(write_plan(_plan(_two_rooms()))).rooms) == 2


# -- entrances ------------------------------------------------------------------------------


def test_read__no_exterior_doors_unless_asked(write_plan):
    assert read(write_plan(_plan(_two_rooms(a_label="ENTRANCE")))).entrances == ()


def test_read__infer_entrances_puts_a_door_on_the_entrance_outer_wall(write_plan):
    b = read(write_plan(_plan(_two_rooms(a_label="ENTRANCE"))), infer_entrances=True)
    (door,) = b.entrances
    assert door.room_a == "A"
    assert b.room("A").polygon.exterior.distance(_point(door)) < 1e-9
    assert door.x == pytest.approx(5.0)  # middle of A's longest outer wall (top or bottom, 10 m)
    assert b.metadata["inferred_entrances"]["rule"] == "entrance spaces"
    assert not b.validate()


def test_read__infer_entrances_falls_back_to_a_hall_then_a_corridor(write_plan):
    b = read(write_plan(_plan(_two_rooms())), infer_entrances=True)
    (door,) = b.entrances
    assert door.room_a == "B"
    assert b.metadata["inferred_entrances"]["rule"] == "largest corridor"
    assert not b.validate()


def _point(door):
    from shapely.geometry import Point

    return Point(door.x, door.y)


# -- labels ---------------------------------------------------------------------------------


def test_read__unknown_label_names_space_and_how_to_add_it(write_plan):
    path = write_plan(_plan(_two_rooms(a_label="ROBOT GARAGE")))
    with pytest.raises(PlanFormatError) as e:
        read(path)
    _assert_one_line_error(e, str(path), 'space id="A"', "robot garage", "label_map")


def test_read__label_map_dict_adds_a_label(write_plan):
    b = read(write_plan(_plan(_two_rooms(a_label="ROBOT GARAGE"))), {"Robot Garage": "B"})
    assert (b.room("A").function, b.room("A").label) == ("robot garage", SemanticLabel.BIG)


def test_read__label_map_json_file_overrides_a_label(write_plan, tmp_path):
    table = tmp_path / "labels.json"
    table.write_text(json.dumps({"office": "small"}))
    assert read(write_plan(_plan(_two_rooms())), label_map=table).room("A").label is SemanticLabel.SMALL


@pytest.mark.parametrize(
    ("function", "label"),
    [
        ("corridor", "corridor"),
        ("lobby", "hall"),
        ("entrance", "hall"),
        ("classroom", "medium"),
        ("conference room", "medium"),
        ("washroom", "small"),
        ("stairs", "small"),
        ("shared office", "big"),
        ("canteen", "big"),
        ("toilet", "small"),
        ("bedroom", "medium"),
        ("living room", "big"),
    ],
)
def test_label_map__default_table(function, label):
    assert semantic_label_for(function) is SemanticLabel(label)


def test_label_map__override_updates_default():
    table = load_label_map({"Server_Room": "M", "office": SemanticLabel.BIG})
    assert table["server room"] is SemanticLabel.MEDIUM
    assert table["office"] is SemanticLabel.BIG
    assert table["classroom"] is SemanticLabel.MEDIUM
    assert load_label_map()["office"] is SemanticLabel.MEDIUM


def test_label_map__json_file_flat_or_nested(tmp_path):
    flat, nested = tmp_path / "flat.json", tmp_path / "nested.json"
    flat.write_text('{"boiler room": "small"}')
    nested.write_text('{"_about": "mine", "labels": {"boiler room": "small"}}')
    assert load_label_map(flat)["boiler room"] is SemanticLabel.SMALL
    assert load_label_map(nested)["boiler room"] is SemanticLabel.SMALL


def test_label_map__bad_value_and_bad_file_are_config_errors(tmp_path):
    with pytest.raises(ConfigError, match=r"'office'.*valid values"):
        load_label_map({"office": "huge"})
    broken = tmp_path / "broken.json"
    broken.write_text("{not json")
    with pytest.raises(ConfigError, match=r"broken\.json.*not valid JSON"):
        load_label_map(broken)
    with pytest.raises(ConfigError, match="cannot read"):
        load_label_map(tmp_path / "missing.json")


def test_label_map__unknown_function_says_how_to_add_it():
    with pytest.raises(ConfigError, match=r"unknown functional label 'boiler room'.*label_map"):
        semantic_label_for("BOILER ROOM")


# -- bad input ------------------------------------------------------------------------------


def test_read__missing_file(tmp_path):
    with pytest.raises(PlanFormatError) as e:
        read(tmp_path / "nope.xml")
    _assert_one_line_error(e, "nope.xml", "no such file")


def test_read__malformed_xml_gives_line_and_column(write_plan):
    path = write_plan('<?xml version="1.0"?>\n<building>\n  <scale></building>\n')
    with pytest.raises(PlanFormatError) as e:
        read(path)
    _assert_one_line_error(e, str(path), "malformed XML at line 3, column", "mismatched tag")


@pytest.mark.parametrize(
    ("scale", "element"),
    [
        (None, "scale"),
        ("<value>0</value><um>pixel</um>", "scale/represented_distance/value"),
        ("<value>ten</value><um>pixel</um>", "scale/represented_distance/value"),
        ("<um>pixel</um>", "scale/represented_distance/value"),
    ],
)
def test_read__missing_or_zero_scale(write_plan, scale, element):
    path = write_plan(_plan(_two_rooms(), scale=scale))
    with pytest.raises(PlanFormatError) as e:
        read(path)
    _assert_one_line_error(e, str(path), element)


def test_read__unknown_unit(write_plan):
    with pytest.raises(PlanFormatError) as e:
        read(write_plan(_plan(_two_rooms(), real="<value>1</value><um>cubit</um>")))
    _assert_one_line_error(e, "scale/real_distance/um", "cubit", "cm")


def test_read__non_numeric_coordinate_names_space_and_point(write_plan):
    text = _plan(_two_rooms()).replace('<point x="300" y="100"/>', '<point x="3OO" y="100"/>', 1)
    path = write_plan(text)
    with pytest.raises(PlanFormatError) as e:
        read(path)
    _assert_one_line_error(e, str(path), 'space id="A"', "point 2", "'3OO'")


def test_read__figure_eight_outline_is_an_error(write_plan):
    bowtie = [(0, 0), (100, 100), (100, 0), (0, 100)]
    path = write_plan(_plan([_space("X", "OFFICE", bowtie)]))
    with pytest.raises(PlanFormatError) as e:
        read(path)
    _assert_one_line_error(e, str(path), 'space id="X"', "not a simple polygon", "<bounding_polygon>")


def test_read__empty_space_with_portals_is_an_error(write_plan):
    spaces = [_space("A", "OFFICE", [(5, 5), (5, 5), (5, 5)], [], [("p1", ("A", "B"))]), _two_rooms()[1]]
    with pytest.raises(PlanFormatError, match=r'space id="A".*encloses no area'):
        read(write_plan(_plan(spaces)))


def test_read__portal_to_unknown_space_is_an_error(write_plan):
    path = write_plan(_plan(_two_rooms(portal_targets=("A", "Z"))))
    with pytest.raises(PlanFormatError) as e:
        read(path)
    _assert_one_line_error(e, 'portal linesegment="p1"', "'Z'")


def test_read__not_a_floor_plan(write_plan):
    with pytest.raises(PlanFormatError, match="root element is <world>"):
        read(write_plan("<world width='2' depth='2' name='w'/>"))


def test_read__no_spaces(write_plan):
    with pytest.raises(PlanFormatError, match="no rooms"):
        read(write_plan(_plan([])))


def test_read__bad_door_width_is_a_config_error(write_plan):
    with pytest.raises(ConfigError, match="door_width_m"):
        read(write_plan(_plan(_two_rooms())), door_width_m=0)


# -- writing --------------------------------------------------------------------------------


def assert_same_building(back, original, tol=1e-6):
    assert back.building_type == original.building_type
    assert [r.id for r in back.rooms] == [r.id for r in original.rooms]
    for r, s in zip(back.rooms, original.rooms, strict=True):
        assert (r.label, r.function) == (s.label, s.function)
        assert len(r.outline) == len(s.outline)
        for p, q in zip(r.outline, s.outline, strict=True):
            assert p == pytest.approx(q, abs=tol)
    assert [d.id for d in back.doors] == [d.id for d in original.doors]
    for d, e in zip(back.doors, original.doors, strict=True):
        assert d.rooms == e.rooms
        assert (d.x, d.y, d.width_m) == pytest.approx((e.x, e.y, e.width_m), abs=tol)
        assert math.sin(d.angle_rad - e.angle_rad) == pytest.approx(0, abs=tol)


def test_write__round_trip_keeps_rooms_doors_and_entrances(tiny_office, tmp_path):
    path = tmp_path / "tiny.xml"
    assert save(tiny_office, path) == [path]
    back = load(path)
    assert_same_building(back, tiny_office)
    assert [d.id for d in back.entrances] == ["e1"]


def test_write__uses_one_pixel_per_centimetre_with_y_down(tiny_office, tmp_path):
    path = tmp_path / "tiny.xml"
    write(tiny_office, path)
    root = ET.parse(path).getroot()
    assert root.findtext("scale/represented_distance/value") == "100"
    assert root.findtext("scale/real_distance/um") == "cm"
    assert root.findtext("building_type/main_type") == "OFFICE"
    corridor = root.find("floor/spaces/space[@id='c']")
    ys = {float(p.get("y")) for p in corridor.findall("bounding_polygon/point")}
    assert ys == {400.0, 600.0}  # the corridor is at the bottom of the plan: largest pixel y
    assert corridor.findtext("labels/type") == "C"
    assert corridor.findtext("labels/label") == "CORRIDOR"


def test_write__doors_are_portal_segments_of_their_width_listed_by_both_rooms(tiny_office, tmp_path):
    path = tmp_path / "tiny.xml"
    write(tiny_office, path)
    root = ET.parse(path).getroot()
    copies = root.findall("floor/spaces/space/space_representation/linesegment[@id='d1']")
    assert len(copies) == 2
    for seg in copies:
        assert seg.findtext("class") == "PORTAL"
        (x0, y0), (x1, y1) = [(float(p.get("x")), float(p.get("y"))) for p in seg.findall("point")]
        assert math.hypot(x1 - x0, y1 - y0) == pytest.approx(90.0)
    exterior = root.findall("floor/spaces/space/portals/portal[linesegment='e1']/target/id")
    assert [t.text for t in exterior] == ["c"]


def test_write__semantic_label_survives_even_against_the_table(tiny_office, tmp_path):
    from realistic_indoor.building import Building, Room

    big_office = Room("b", "big", "office", tiny_office.room("b").outline)
    b = Building("office", (*tiny_office.rooms[:2], big_office), tiny_office.doors)
    path = tmp_path / "big.xml"
    write(b, path)
    assert load(path).room("b").label is SemanticLabel.BIG


@pytest.mark.parametrize("name", ["office/ED21.xml", "school/virginia_cross_updated.xml"])
def test_write__round_trip_of_a_real_plan(real_plans_dir, tmp_path, name):
    b = load(real_plans_dir / name)
    save(b, tmp_path / "plan.xml")
    assert_same_building(load(tmp_path / "plan.xml"), b)


def test_write__empty_building_is_a_config_error(tmp_path):
    from realistic_indoor.building import Building

    with pytest.raises(ConfigError, match="without rooms"):
        write(Building("office", ()), tmp_path / "empty.xml")


def test_label_map__knows_every_function_the_generators_use():
    from realistic_indoor.generator import GENERATOR_NAMES, generate
    from realistic_indoor.io.function_labels import load_label_map

    known = load_label_map(None)
    used = {
        r.function for name in GENERATOR_NAMES for seed in range(20) for r in generate(name, seed=seed).rooms
    }
    assert sorted(used - set(known)) == []
