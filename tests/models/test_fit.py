from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from realistic_indoor.building import ROOM_LABELS, Building, Door, Room, SemanticLabel, check_building
from realistic_indoor.errors import ConfigError
from realistic_indoor.generator import generate, make_generator
from realistic_indoor.models import BuildingTypeModel, fit_model
from realistic_indoor.models.building_model import FootprintHabits, RoomDensity
from realistic_indoor.validator.tables import label_table


@pytest.fixture(scope="module")
def offices():
    return [generate("office", 1500, seed=s) for s in range(12)]


def test_fit_model__recovers_the_shares_and_doors_of_its_plans(offices):
    model, table = fit_model(offices, skip_misscaled=False), label_table(offices)
    assert model.name == "office"
    for lab in SemanticLabel:
        assert model.labels[lab].share * 100 == pytest.approx(table[lab]["share_pct"])
        assert model.labels[lab].doors_mean == pytest.approx(table[lab]["doors_mean"])
        assert model.labels[lab].area_mean == pytest.approx(table[lab]["area_mean"])


def test_fit_model__connections_count_every_doorway(offices):
    model = fit_model(offices)
    doors_to = {
        lab: sum(1 for b in offices for r in b.rooms if r.label is lab for _ in b.doors_of[r.id])
        for lab in SemanticLabel
    }
    hall_to_outside = sum(
        1 for b in offices for d in b.entrances if b.room(d.room_a).label is SemanticLabel.HALL
    )
    assert model.connection(SemanticLabel.HALL, "outside") == pytest.approx(
        hall_to_outside / doors_to[SemanticLabel.HALL]
    )


def test_fit_model__functions_and_structures_come_from_the_plans(offices):
    model = fit_model(offices)
    assert "office" in model.functions[SemanticLabel.MEDIUM]
    assert "corridor" in model.functions[SemanticLabel.CORRIDOR]
    assert 0.0 < model.structures.clustered_small_rooms <= 1.0
    assert 0.0 <= model.structures.connected_room_pairs < 0.3


def test_fit_model__names_mixed_sets_unknown_and_takes_a_name():
    mixed = [generate("office", 800, seed=1), generate("house", 150, seed=1)]
    assert fit_model(mixed).name == "unknown"
    assert fit_model(mixed, name="hospital").name == "hospital"


def test_fit_model__without_rooms_is_a_config_error():
    with pytest.raises(ConfigError, match="without rooms"):
        fit_model([])


def test_fit_model__a_new_type_gets_a_generator(offices):
    model = fit_model(offices, name="hospital")
    b = make_generator("hospital", 1200, model=model)(np.random.default_rng(0))
    assert b.building_type.value == "unknown"
    assert b.metadata["params"]["model"] == "hospital"
    assert check_building(b) == []


@pytest.mark.parametrize("kind", ["office", "school"])
def test_fit_model__on_the_real_plans_gives_a_generator_of_their_statistics(kind, real_plans_dir: Path):
    from realistic_indoor.io import load

    plans = [load(p) for p in sorted((real_plans_dir / kind).glob("*.xml"))]
    model = fit_model(plans)
    assert isinstance(model, BuildingTypeModel)
    assert model.name == kind
    gen = make_generator(kind, model=model)
    built = [gen(np.random.default_rng(s)) for s in range(40)]
    assert all(check_building(b) == [] for b in built)
    table = label_table(built)
    for lab in SemanticLabel:
        assert table[lab]["share_pct"] == pytest.approx(100 * model.labels[lab].share, abs=8.0), lab
    for lab in ROOM_LABELS:
        assert table[lab]["doors_mean"] == pytest.approx(model.labels[lab].doors_mean, abs=0.3), lab


def _row_of_rooms(side_m: float, n: int) -> Building:
    """``n`` square rooms of ``side_m`` in a row along a corridor, one door each."""
    rooms = [Room.rectangle("c", "corridor", "corridor", (0.0, 0.0, n * side_m, 2.0))]
    doors = [Door("e", "c", None, 0.0, 1.0, 1.0, np.pi / 2)]
    for k in range(n):
        rooms.append(
            Room.rectangle(f"r{k}", "medium", "classroom", (k * side_m, 2.0, (k + 1) * side_m, 2.0 + side_m))
        )
        doors.append(Door(f"d{k}", "c", f"r{k}", (k + 0.5) * side_m, 2.0, 0.9, 0.0))
    return Building("school", tuple(rooms), tuple(doors), {})


def test_fit_model__room_areas_growing_with_floor_area_give_the_exponent():
    # rooms of sides 6, 8, 10 m (4, 8, 16 of them) off a 2 m corridor: floor areas 192, 640 and
    # 1,920 m2, medium rooms 36, 64, 100 m2, corridors 48, 128, 320 m2. The exponent is the
    # weighted least-squares slope of log(area / the label's mean) on log(floor area), one
    # point per plan and label weighted by its rooms; computed here with numpy's polyfit.
    plans = [_row_of_rooms(side, n) for side, n in ((6.0, 4), (8.0, 8), (10.0, 16))]
    assert [b.area for b in plans] == [192.0, 640.0, 1920.0]
    x = np.log([192.0, 640.0, 1920.0] * 2)
    medium_mean, corridor_mean = (4 * 36 + 8 * 64 + 16 * 100) / 28, (48 + 128 + 320) / 3
    y = np.log(
        [
            36 / medium_mean,
            64 / medium_mean,
            100 / medium_mean,
            48 / corridor_mean,
            128 / corridor_mean,
            320 / corridor_mean,
        ]
    )
    w = np.array([4, 8, 16, 1, 1, 1])
    expected = np.polyfit(x, y, 1, w=np.sqrt(w))[0]
    scaling = fit_model(plans, skip_misscaled=False).size_scaling
    assert scaling.exponent == pytest.approx(expected, abs=1e-4)
    assert scaling.reference_area_m2 == pytest.approx(np.exp(np.average(x, weights=w)), abs=0.1)


def test_fit_model__plans_of_one_size_give_no_scaling():
    plans = [_row_of_rooms(6.0, 4) for _ in range(3)]
    assert fit_model(plans, skip_misscaled=False).size_scaling.exponent == 0.0


def test_at_area__sizes_rooms_for_the_density_line():
    # rows of 4 rooms of 6 m, 8 of 8 m, 16 of 10 m (rooms 6 x 5 m ... wide, see _row_of_rooms):
    # the model's line gives a density per floor area; at_area without a draw scales every
    # label's area so that 10,000 m2 over the mean room area is that density
    model = fit_model(
        [_row_of_rooms(s, n) for s, n in ((6.0, 4), (8.0, 8), (10.0, 16))], skip_misscaled=False
    )
    assert model.density.per_hectare > 0
    for area in (500.0, 2000.0):
        sized = model.at_area(area)
        assert 10_000.0 / sized.mean_room_area() == pytest.approx(model.density.at(area))
        factor = sized.mean_room_area() / model.mean_room_area()
        for lab in SemanticLabel:
            assert sized.stats(lab).area_mean == pytest.approx(model.stats(lab).area_mean * factor)


def test_at_area__scales_every_label_area_by_the_factor():
    model = fit_model(
        [_row_of_rooms(s, n) for s, n in ((6.0, 4), (8.0, 8), (10.0, 16))], skip_misscaled=False
    )
    model = replace(model, density=RoomDensity())  # no density: the size scaling sizes the rooms
    ref = model.size_scaling.reference_area_m2
    bigger = model.at_area(ref * 4)
    factor = min(4**model.size_scaling.exponent, 2.0)
    for lab in SemanticLabel:
        assert bigger.stats(lab).area_mean == pytest.approx(model.stats(lab).area_mean * factor)
    assert model.at_area(ref) is model


def test_fit_model__door_habits_count_plans_with_one_door_per_room():
    # two plans whose rooms have one door each (none_share 2/3), and one of 8 rooms with a
    # corridor door each plus 4 doors joining rooms 0-1, 2-3, 4-5, 6-7: 16 room-doors for 8
    # rooms, one further door per room (mean_rate 1)
    plain = [_row_of_rooms(6.0, 4), _row_of_rooms(8.0, 4)]
    busy = _row_of_rooms(6.0, 8)
    extra = tuple(
        Door(f"x{k}", f"r{k}", f"r{k + 1}", (k + 1) * 6.0, 5.0, 0.9, np.pi / 2) for k in range(0, 8, 2)
    )
    busy = Building("school", busy.rooms, busy.doors + extra, {})
    habits = fit_model([*plain, busy], skip_misscaled=False).door_habits
    assert habits.none_share == pytest.approx(2 / 3, abs=1e-4)
    assert habits.mean_rate == pytest.approx(1.0)


def test_door_habits__draw_none_at_the_share_and_the_mean_otherwise():
    from realistic_indoor.models.building_model import DoorHabits

    rng = np.random.default_rng(0)
    draws = np.array([DoorHabits(0.3, 0.5).draw(rng) for _ in range(20000)])
    assert (draws == 0).mean() == pytest.approx(0.3, abs=0.01)
    assert draws[draws > 0].mean() == pytest.approx(0.5, abs=0.02)


def test_fit_model__ring_share_counts_plans_whose_corridors_close_a_loop():
    tree = _row_of_rooms(6.0, 4)
    # two more corridors under the first, each joined to it and to the other: a loop of three
    extra = (
        Room.rectangle("c2", "corridor", "corridor", (0.0, -2.0, 12.0, 0.0)),
        Room.rectangle("c3", "corridor", "corridor", (12.0, -2.0, 24.0, 0.0)),
    )
    doors = (
        Door("j1", "c", "c2", 6.0, 0.0, 0.9, 0.0),
        Door("j2", "c", "c3", 18.0, 0.0, 0.9, 0.0),
        Door("j3", "c2", "c3", 12.0, -1.0, 0.9, np.pi / 2),
    )
    ring = Building("school", (*tree.rooms, *extra), tree.doors + doors, {})
    structures = fit_model([tree, tree, ring, ring], skip_misscaled=False).structures
    assert structures.ring_share == pytest.approx(0.5)


def _chain(side_m: float, n: int) -> Building:
    """``n`` square rooms of ``side_m`` in a row, each opening into the next: 10,000 / side^2 rooms per hectare."""
    rooms = tuple(
        Room.rectangle(f"r{k}", "medium", "office", (k * side_m, 0.0, (k + 1) * side_m, side_m))
        for k in range(n)
    )
    doors = tuple(
        Door(f"d{k}", f"r{k}", f"r{k + 1}", (k + 1) * side_m, side_m / 2, 0.9, np.pi / 2)
        for k in range(n - 1)
    )
    return Building("office", rooms, doors, {})


def test_fit_model__room_density_line_through_plans_of_one_density():
    # rooms of 5 x 5 m: 400 rooms per hectare at 100, 200 and 400 m2 (4, 8, 16 rooms): a flat
    # line at 400 through the geometric mean area 200 m2, no spread; a plan drawn at ten times
    # the scale (4 rooms per hectare) lies far off the line and is left out of it
    plans = [_chain(5.0, n) for n in (4, 8, 16)]
    for density in (
        fit_model(plans, skip_misscaled=False).density,
        fit_model([*plans, _chain(50.0, 6)], skip_misscaled=False).density,
    ):
        assert density.per_hectare == pytest.approx(400.0)
        assert density.reference_area_m2 == pytest.approx(200.0)
        assert density.exponent == 0.0
        assert density.spread == pytest.approx(0.0)


def _ell(side_m: float) -> Building:
    """Three square rooms of ``side_m`` in an L, each opening into the next.

    Floor 3 side^2, convex hull 3.5 side^2 (the square of 2 side less the half-square cut off
    at the L's open corner): convex fill 6/7 = 0.857.
    """
    s = side_m
    rooms = (
        Room.rectangle("a", "medium", "office", (0.0, 0.0, s, s)),
        Room.rectangle("b", "medium", "office", (s, 0.0, 2 * s, s)),
        Room.rectangle("c", "medium", "office", (0.0, s, s, 2 * s)),
    )
    doors = (
        Door("d0", "a", "b", s, s / 2, 0.9, np.pi / 2),
        Door("d1", "a", "c", s / 2, s, 0.9, 0.0),
    )
    return Building("office", rooms, doors, {})


def test_fit_model__composed_share_counts_footprints_that_are_not_one_block():
    # three rows of rooms (convex fill 1) and one L (6/7, below COMPOSED_FILL 0.9): a quarter
    plans = [_chain(5.0, n) for n in (4, 8, 16)] + [_ell(5.0)]
    assert fit_model(plans, skip_misscaled=False).footprint.composed_share == pytest.approx(0.25)
    assert fit_model(plans[:3], skip_misscaled=False).footprint.composed_share == 0.0


def test_footprint_habits__a_model_file_without_the_share_leaves_it_to_the_layout():
    # model files written before composed_share read as -1: the layout's own frequencies
    assert FootprintHabits(aspect_median=1.5, aspect_spread=0.3).composed_share == -1.0
    with pytest.raises(ConfigError, match="composed_share"):
        FootprintHabits(composed_share=1.5)


def test_fit_model__room_density_slope_is_held_to_the_square_root_law():
    # 4 rooms at every size (rooms of 5, 10 and 20 m): density falls as 1 / area (slope -1),
    # which a type's buildings do not do; the slope is held at -0.5
    density = fit_model([_chain(side, 4) for side in (5.0, 10.0, 20.0)], skip_misscaled=False).density
    assert density.exponent == -0.5


def test_room_density__draws_stay_within_two_spreads_of_the_line():
    density = RoomDensity(per_hectare=200.0, reference_area_m2=1000.0, exponent=-0.5, spread=0.3)
    rng = np.random.default_rng(0)
    draws = np.array([density.draw(rng, 4000.0) for _ in range(2000)])
    assert density.at(4000.0) == pytest.approx(100.0)
    assert np.all(np.abs(np.log(draws / 100.0)) <= 0.6 + 1e-12)
    assert np.std(np.log(draws / 100.0)) == pytest.approx(0.3, abs=0.03)


def test_room_density__a_model_file_with_an_absurd_density_is_one_line():
    with pytest.raises(ConfigError, match=r"RoomDensity\.spread must be a finite number in"):
        RoomDensity(per_hectare=200.0, spread=float("nan"))
