"""Tolerant import of floor-plan XML: one small hand-written plan per defect, repaired with a
warning by default and refused under ``strict``; the shared real plans after repair.

Every plan is in pixels, y down, 10 px = 50 cm (0.05 m/px). After the flip and the move to
(0, 0), pixel (x, y) of a plan whose spaces span x >= 100 and y <= 200 is metre
((x - 100) * 0.05, (200 - y) * 0.05). Room A is 200 x 100 px (10 m x 5 m), room B to its right
100 x 100 px; they share the wall x = 300 px (10 m).
"""

import math
import warnings

import pytest

from realistic_indoor.cli import main
from realistic_indoor.errors import PlanFormatError
from realistic_indoor.io import load
from realistic_indoor.io.floorplan import PlanRepairWarning
from realistic_indoor.io.floorplan_xml import read

A_RING = [(100, 100), (300, 100), (300, 200), (100, 200)]
B_RING = [(300, 100), (400, 100), (400, 200), (300, 200)]
C_RING = [(600, 100), (700, 100), (700, 200), (600, 200)]  # 15 m right of A, 10 m right of B
MID = (300, 150)  # the middle of the wall A and B share: (10, 2.5) m


def _space(sid, ring, segments=(), portals=(), label="OFFICE"):
    pts = "".join(f'<point x="{x}" y="{y}"/>' for x, y in [*ring, ring[0]])
    segs = "".join(
        f'<linesegment id="{i}"><point x="{p[0]}" y="{p[1]}"/><point x="{q[0]}" y="{q[1]}"/>'
        "<class>PORTAL</class></linesegment>"
        for i, p, q in segments
    )
    ports = "".join(
        f"<portal><linesegment>{i}</linesegment><target>{''.join(f'<id>{t}</id>' for t in ts)}</target></portal>"
        for i, ts in portals
    )
    return (
        f'<space id="{sid}"><labels><label>{label}</label></labels><bounding_polygon>{pts}</bounding_polygon>'
        f"<space_representation>{segs}</space_representation><portals>{ports}</portals></space>"
    )


def _plan(*spaces):
    return (
        '<building id="b"><scale><represented_distance><value>10</value><um>pixel</um>'
        "</represented_distance><real_distance><value>50</value><um>cm</um></real_distance></scale>"
        "<building_type><main_type>OFFICE</main_type></building_type>"
        f"<floor><spaces>{''.join(spaces)}</spaces></floor></building>"
    )


def _at(point):
    """A zero-length segment copy at ``point`` (pixels)."""
    return (point, point)


@pytest.fixture
def plan_file(tmp_path):
    def _write(*spaces):
        path = tmp_path / "plan.xml"
        path.write_text(_plan(*spaces), encoding="utf-8")
        return path

    return _write


def _read_warned(path):
    """Read ``path``; return the building and the messages of its repair warnings."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        b = read(path)
    messages = [str(w.message) for w in caught if issubclass(w.category, PlanRepairWarning)]
    assert len(messages) == len(caught), [str(w.message) for w in caught]
    return b, messages


def _assert_names(message, *parts):
    assert "\n" not in message
    for part in parts:
        assert part in message, f"{part!r} not in {message!r}"


def _refused(path, *parts):
    with pytest.raises(PlanFormatError) as e:
        read(path, strict=True)
    _assert_names(str(e.value), str(path), *parts, "without strict")
    with pytest.raises(PlanFormatError):
        load(path, strict=True)


# -- a good plan ------------------------------------------------------------------------------


def test_good_plan__no_warning_no_repair_and_strict_reads_it(plan_file):
    path = plan_file(
        _space("A", A_RING, [("p1", *_at(MID))], [("p1", ("A", "B"))]),
        _space("B", B_RING, [("p1", *_at(MID))], [("p1", ("A", "B"))], label="CORRIDOR"),
    )
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        b = read(path)
    assert read(path, strict=True) == b
    assert "repairs" not in b.metadata and "wall_tolerance_m" not in b.metadata
    assert not b.validate(require_entrance=False)


# -- (a) spaces give different targets for one portal -------------------------------------------


def test_targets_differ__the_door_joins_the_spaces_the_segment_touches(plan_file):
    # A says p1 joins A and B, B says B and C; the segment at (300, 150) is on the walls of A and
    # B, 300 px (15 m) from C: the door joins A and B.
    path = plan_file(
        _space("A", A_RING, [("p1", *_at(MID))], [("p1", ("A", "B"))]),
        _space("B", B_RING, [("p1", *_at(MID))], [("p1", ("B", "C"))]),
        _space("C", C_RING),
    )
    b, (message,) = _read_warned(path)
    (door,) = b.doors
    assert set(door.rooms) == {"A", "B"}
    assert (door.x, door.y) == pytest.approx((10.0, 2.5))
    _assert_names(message, str(path), 'portal linesegment="p1"', '"A"', '"B"', '"C"', "different targets")
    assert b.metadata["repairs"][0]["defect"] == "targets_differ"
    _refused(path, 'portal linesegment="p1"', 'space "A" names ["A", "B"]', 'space "B" names ["B", "C"]')


def test_targets_differ__of_three_spaces_near_the_segment_the_two_nearest(plan_file):
    # D lies below B (y 200..300 px). The segment at (300, 198) is on the walls of A and B (x = 300)
    # and 2 px (0.1 m) from D's top wall y = 200: all three within 0.3 m, A and B the nearest.
    d_ring = [(300, 200), (400, 200), (400, 300), (300, 300)]
    seg = _at((300, 198))
    path = plan_file(
        _space("A", A_RING, [("p1", *seg)], [("p1", ("A", "B"))]),
        _space("B", B_RING, [("p1", *seg)]),
        _space("D", d_ring, [("p1", *seg)], [("p1", ("A", "D"))]),
    )
    b, (message,) = _read_warned(path)
    (door,) = b.doors
    assert set(door.rooms) == {"A", "B"}
    assert '"D"' in message and "the two nearest kept" in message


def test_targets_differ__dropped_when_the_segment_touches_one_space(plan_file):
    # p2 lies on C's left wall (600, 150): 15 m from A, 10 m from B. A names A and C, C names B
    # and C: only C is near, so no door can be made; the good door p1 stays.
    path = plan_file(
        _space("A", A_RING, [("p1", *_at(MID))], [("p1", ("A", "B")), ("p2", ("A", "C"))]),
        _space("B", B_RING, [("p1", *_at(MID))], [("p1", ("A", "B"))]),
        _space("C", C_RING, [("p2", *_at((600, 150)))], [("p2", ("B", "C"))]),
    )
    b, (message,) = _read_warned(path)
    assert [d.id for d in b.doors] == ["p1"]
    _assert_names(message, 'portal linesegment="p2"', "dropped the door")
    _refused(path, 'portal linesegment="p2"')


# -- (b) a portal listed by one of its spaces only ----------------------------------------------


def test_one_sided_portal__kept_when_it_lies_on_both_walls(plan_file):
    path = plan_file(
        _space("A", A_RING, [("p1", *_at(MID))], [("p1", ("A", "B"))]),
        _space("B", B_RING),
    )
    b, (message,) = _read_warned(path)
    (door,) = b.doors
    assert set(door.rooms) == {"A", "B"}
    assert (door.x, door.y) == pytest.approx((10.0, 2.5))
    _assert_names(message, str(path), 'portal linesegment="p1"', 'only space "A" lists it', '"B"', "kept")
    assert not b.validate(require_entrance=False)
    _refused(path, 'portal linesegment="p1"', 'only space "A" lists it')


def test_one_sided_portal__dropped_when_off_the_other_space(plan_file):
    # The segment is on A's wall (300, 150); C's nearest wall is x = 600 px: 15 m away.
    path = plan_file(
        _space("A", A_RING, [("p1", *_at(MID))], [("p1", ("A", "C"))]),
        _space("C", C_RING),
    )
    b, (message,) = _read_warned(path)
    assert b.doors == ()
    _assert_names(message, 'portal linesegment="p1"', '"C"', "dropped the door", "15.00 m")


def test_one_sided_portal__without_a_segment_is_dropped(plan_file):
    path = plan_file(_space("A", A_RING, portals=[("p1", ("A", "B"))]), _space("B", B_RING))
    b, (message,) = _read_warned(path)
    assert b.doors == ()
    assert "no space gives its segment" in message


# -- (c) a door off the walls of a room it joins ---------------------------------------------------


def test_door_off_wall__moved_to_the_shared_wall(plan_file):
    # Both copies at (200, 150): the middle of A, (5, 2.5) m, 2.5 m from A's walls and 5 m from
    # B's. The door moves to the middle of the wall they share, x = 10 m from y = 0 to 5.
    seg = _at((200, 150))
    path = plan_file(
        _space("A", A_RING, [("p1", *seg)], [("p1", ("A", "B"))]),
        _space("B", B_RING, [("p1", *seg)], [("p1", ("A", "B"))]),
    )
    b, (message,) = _read_warned(path)
    (door,) = b.doors
    assert (door.x, door.y, door.width_m) == pytest.approx((10.0, 2.5, 0.9))
    assert door.angle_rad == pytest.approx(math.pi / 2)
    _assert_names(
        message, 'portal linesegment="p1" of spaces "A", "B"', '5.00 m from the outline of space "B"'
    )
    assert not b.validate(require_entrance=False)
    _refused(path, 'portal linesegment="p1"', '"B"')


def test_door_off_wall__dropped_between_rooms_too_far_apart(plan_file):
    # A's copy on its wall x = 300 px, C's on its wall x = 600 px: 15 m apart, no door joins them.
    path = plan_file(
        _space("A", A_RING, [("p1", *_at(MID))], [("p1", ("A", "C"))]),
        _space("C", C_RING, [("p1", *_at((600, 150)))], [("p1", ("A", "C"))]),
    )
    b, (message,) = _read_warned(path)
    assert b.doors == ()
    _assert_names(message, "dropped the door", "15.00 m apart")


def test_door_in_a_thick_wall__tolerated_without_warning(plan_file):
    # B starts at x = 304 px: a wall 4 px (0.2 m) thick. The copies on each side give a door at
    # (302, 150) px, 0.1 m from each outline: off the 0.05 m tolerance, inside the 0.3 m one.
    b_ring = [(304, 100), (400, 100), (400, 200), (304, 200)]
    path = plan_file(
        _space("A", A_RING, [("p1", *_at(MID))], [("p1", ("A", "B"))]),
        _space("B", b_ring, [("p1", *_at((304, 150)))], [("p1", ("A", "B"))]),
    )
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        b = read(path, strict=True)
    (door,) = b.doors
    assert (door.x, door.y) == pytest.approx((10.1, 2.5))
    assert b.metadata["wall_tolerance_m"] == 0.3
    assert not b.validate(require_entrance=False)
    assert [f.code for f in b.validate(require_entrance=False, wall_tolerance_m=0.05)] == ["door_off_wall"]


# -- (d) overlapping outlines ---------------------------------------------------------------------


def test_overlap__cut_out_of_the_larger_room(plan_file):
    # B is drawn from x = 290 px: it overlaps A by 10 x 100 px = 2.5 m2. A (50 m2) is larger
    # than B (110 x 100 px = 27.5 m2), so A gives up the overlap: 190 x 100 px = 47.5 m2.
    b_ring = [(290, 100), (400, 100), (400, 200), (290, 200)]
    seg = _at((290, 150))
    path = plan_file(
        _space("A", A_RING, [("p1", *seg)], [("p1", ("A", "B"))]),
        _space("B", b_ring, [("p1", *seg)], [("p1", ("A", "B"))]),
    )
    b, (message,) = _read_warned(path)
    assert b.room("A").bounds == pytest.approx((0, 0, 9.5, 5))
    assert b.room("A").area == pytest.approx(47.5)
    assert b.room("B").bounds == pytest.approx((9.5, 0, 15, 5))
    _assert_names(
        message,
        str(path),
        'space id="B" and space id="A"',
        "overlap by 2.50 m2",
        'larger space "A" (50.00 m2 -> 47.50 m2)',
    )
    assert not b.validate(require_entrance=False)
    _refused(path, 'space id="B" and space id="A"', "overlap by 2.50 m2")


def test_overlap__of_equal_rooms_the_later_one_gives_way(plan_file):
    # B2 spans x 290..490 px: as large as A (50 m2), later in the file, so it loses 2.5 m2.
    b_ring = [(290, 100), (490, 100), (490, 200), (290, 200)]
    path = plan_file(_space("A", A_RING), _space("B2", b_ring))
    b, (message,) = _read_warned(path)
    assert b.room("A").area == pytest.approx(50.0)
    assert b.room("B2").area == pytest.approx(47.5)
    assert 'larger space "B2"' in message


def test_overlap__a_room_inside_another_without_shared_wall_is_kept_as_given(plan_file):
    # C (50 x 60 px = 7.5 m2) lies inside A touching none of its walls: cutting it out would
    # leave a hole, which a room's outline cannot have.
    inner = [(150, 120), (200, 120), (200, 180), (150, 180)]
    path = plan_file(_space("A", A_RING), _space("C", inner))
    b, (message,) = _read_warned(path)
    assert b.room("A").area == pytest.approx(50.0)
    _assert_names(message, "overlap by 7.50 m2", "kept both outlines as given")
    assert [f.code for f in b.validate(require_entrance=False)] == ["overlap", "disconnected"]


def test_overlap__a_room_across_another_is_kept_as_given(plan_file):
    # D (20 x 200 px = 10 m2) crosses A from top to bottom: A without D is two 22.5 m2 pieces.
    across = [(190, 50), (210, 50), (210, 250), (190, 250)]
    path = plan_file(_space("A", A_RING), _space("D", across))
    b, (message,) = _read_warned(path)
    assert b.room("A").area == pytest.approx(50.0)
    _assert_names(message, "overlap by 5.00 m2", "split the larger space into 2 pieces")


def test_overlap__a_room_inside_another_touching_its_wall_is_cut_out(plan_file):
    # A closet of 40 x 40 px (4 m2) in A's top-left corner: A keeps 50 - 4 = 46 m2 around it.
    closet = [(100, 100), (140, 100), (140, 140), (100, 140)]
    path = plan_file(_space("A", A_RING), _space("K", closet, label="CLOSET"))
    b, (message,) = _read_warned(path)
    assert b.room("A").area == pytest.approx(46.0)
    assert b.room("K").area == pytest.approx(4.0)
    assert "(50.00 m2 -> 46.00 m2)" in message
    assert not [f for f in b.validate(require_entrance=False) if f.code == "overlap"]


# -- command line ----------------------------------------------------------------------------------


def test_cli__warnings_are_one_line_each_and_strict_refuses(plan_file, capsys):
    b_ring = [(290, 100), (400, 100), (400, 200), (290, 200)]
    path = str(plan_file(_space("A", A_RING, [("p1", *_at(MID))], [("p1", ("A", "B"))]), _space("B", b_ring)))
    assert main(["info", path]) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2  # the overlap, and p1 listed by A only
    assert all(line.startswith("realistic-indoor: warning: ") and path in line for line in err)
    for command in (["info", path], ["convert", path, "-o", path + ".json"]):
        assert main([*command, "--strict"]) == 1
        err = capsys.readouterr().err.strip()
        assert "\n" not in err and "error" in err and 'space id="B" and space id="A"' in err


def test_load__strict_is_accepted_for_every_readable_format(tmp_path, tiny_office):
    from realistic_indoor.io import save

    path = tmp_path / "tiny.json"
    save(tiny_office, path)
    assert load(path, strict=True) == load(path)


# -- the shared real plans ------------------------------------------------------------------------

# What `info --check` reported for Off-2.xml before repairs (16 violated invariants): these six
# overlaps, nine doors between 0.056 and 0.112 m from a room's outline, and no entrance.
OFF2_OVERLAPS = {
    frozenset(p)
    for p in [
        ("a4dce008-63db-48ee-84e5-510162524958", "323421e4-c470-4729-be21-b05abf62222d"),
        ("f1d5a5cd-a5c2-4b2f-ae46-6f4a79f804ad", "7b6f6546-b421-43cc-9803-0a2015fe33ba"),
        ("05e530ac-0378-4fac-af4a-654d3fa70dce", "7e8492f4-a03b-4c6a-adeb-758182ed87d6"),
        ("b39bc9ab-e2ea-460a-8878-449faa8d1869", "7e8492f4-a03b-4c6a-adeb-758182ed87d6"),
        ("0390d41d-a558-422e-8432-4f84ea2e5176", "7b6f6546-b421-43cc-9803-0a2015fe33ba"),
        ("716c0d59-19ee-46ee-804c-3daddec925d3", "8c94b1a7-4f67-4fba-984b-b7b8d5a19526"),
    ]
}
OFF2_OVERLAPS_IDS = {i for p in OFF2_OVERLAPS for i in p}


@pytest.mark.filterwarnings("ignore::realistic_indoor.io.floorplan.PlanRepairWarning")
def test_real_plans__off2_overlaps_are_cut_and_reported(real_plans_dir):
    path = real_plans_dir / "office/Off-2.xml"
    b, messages = _read_warned(path)
    reported = set()
    for m in messages:
        assert "overlap" in m and str(path) in m
        reported.add(frozenset(i for i in OFF2_OVERLAPS_IDS if f'space id="{i}"' in m))
    assert reported == OFF2_OVERLAPS
    assert [f.code for f in b.validate()] == ["no_entrance"]
    assert b.metadata["wall_tolerance_m"] == 0.3
    assert not read(path, infer_entrances=True).validate()
    with pytest.raises(PlanFormatError, match="overlap"):
        read(path, strict=True)


@pytest.mark.filterwarnings("ignore::realistic_indoor.io.floorplan.PlanRepairWarning")
def test_real_plans__only_data_properties_remain(real_plans_dir):
    # Before repairs the 55 plans broke 425 invariants: 286 overlaps, 77 doors off walls, 55
    # without entrance, 7 with rooms no door reaches. The last two are what the files hold.
    codes = []
    for path in sorted(real_plans_dir.glob("*/*.xml")):
        codes += [f.code for f in read(path).validate()]
    assert sorted(set(codes)) == ["disconnected", "no_entrance"]
    assert (codes.count("no_entrance"), codes.count("disconnected")) == (55, 7)
