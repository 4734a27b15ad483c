"""Structures of real schools: classrooms along long corridors, large halls, labs and a gym."""

from realistic_indoor.building import SemanticLabel

C, H = SemanticLabel.CORRIDOR, SemanticLabel.HALL


def _long_side(room):
    x0, y0, x1, y1 = room.bounds
    return max(x1 - x0, y1 - y0)


def test_school__classrooms_open_onto_corridors(samples):
    on_corridor = classrooms = 0
    for b in samples("school"):
        for r in b.rooms:
            if r.function == "classroom":
                classrooms += 1
                on_corridor += any(
                    d.other(r.id) and b.room(d.other(r.id)).label is C for d in b.doors_of[r.id]
                )
    assert classrooms and on_corridor / classrooms >= 0.9


def test_school__classroom_corridors_are_long(samples):
    lengths = []
    for b in samples("school"):
        for r in b.rooms:
            if r.function == "classroom":
                for d in b.doors_of[r.id]:
                    other = d.other(r.id)
                    if other and b.room(other).label is C:
                        lengths.append(_long_side(b.room(other)))
    assert sum(lengths) / len(lengths) >= 10.0


def test_school__every_school_has_a_large_hall_a_lab_and_a_gym(samples):
    for b in samples("school", "paper"):
        functions = {r.function for r in b.rooms}
        assert {"gym", "lab"} <= functions, b.metadata
        assert any(r.label is H and r.area >= 150.0 for r in b.rooms), b.metadata


def test_school__the_default_gym_is_a_big_room_of_at_least_150_m2_almost_always(samples):
    large = 0
    for b in samples("school"):
        assert "lab" in {r.function for r in b.rooms}, b.metadata
        gym = max((r for r in b.rooms if r.function == "gym"), key=lambda r: r.area)
        assert gym.label in (SemanticLabel.BIG, H), b.metadata
        large += gym.label is SemanticLabel.BIG and gym.area >= 150.0
    assert large >= 0.95 * len(samples("school"))


def test_school__the_gym_is_a_hall_reached_from_circulation(samples):
    for b in samples("school"):
        gym = next(r for r in b.rooms if r.function == "gym")
        assert gym.label in (H, SemanticLabel.BIG)
        assert any(d.other(gym.id) and b.room(d.other(gym.id)).label in (C, H) for d in b.doors_of[gym.id])


def test_school__small_rooms_outnumber_classrooms_with_the_papers_model(samples):
    small = sum(r.label is SemanticLabel.SMALL for b in samples("school", "paper") for r in b.rooms)
    medium = sum(r.label is SemanticLabel.MEDIUM for b in samples("school", "paper") for r in b.rooms)
    assert small > 2 * medium


def _large_schools(area_m2, seeds=range(30)):
    import numpy as np

    from realistic_indoor.generator import make_generator

    generate = make_generator("school", area_m2=area_m2)
    return [generate(np.random.default_rng(seed)) for seed in seeds]


def test_large_schools__get_a_canteen_and_an_auditorium_beside_the_gym_often():
    # the shared real schools: 12 of 26 of 1,500 m2 and more have a canteen, 7 of 17 of 2,700 m2
    # and more an auditorium; both come in certainly from 6,000 m2 where they find a place
    schools = _large_schools(9000.0)
    for function, low_m2, high_m2 in (("canteen", 200.0, 400.0), ("conference", 450.0, 850.0)):
        annexes = [
            (b, r)
            for b in schools
            for r in b.rooms
            if r.function == function
            and r.label is SemanticLabel.BIG
            and low_m2 - 1.0 <= r.area <= high_m2 + 1.0
        ]
        assert len({id(b) for b, _ in annexes}) >= 0.3 * len(schools), function
        for b, r in annexes:  # reached from a corridor or hall, like the gym
            assert any(d.other(r.id) and b.room(d.other(r.id)).label in (C, H) for d in b.doors_of[r.id])


def test_small_schools__get_no_canteen_or_auditorium_annex():
    for b in _large_schools(1400.0, range(15)):
        assert not any(r.function in ("canteen", "conference") and r.area >= 300.0 for r in b.rooms)


def test_large_schools__keep_their_floor_area_within_two_percent():
    for area_m2 in (3500.0, 5000.0, 9000.0):
        for b in _large_schools(area_m2, range(12)):
            assert abs(b.area / area_m2 - 1.0) <= 0.02, (area_m2, b.metadata)
