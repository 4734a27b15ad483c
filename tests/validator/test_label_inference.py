import math

import pytest

from realistic_indoor.building import Building, Door, Room, SemanticLabel
from realistic_indoor.validator.label_inference import (
    InferenceRules,
    elongation,
    infer_labels,
    infer_room_label,
    labels_inferred,
    lacks_labels,
    size_thresholds,
)


def test_size_thresholds__geometric_means_of_the_paper_areas():
    t = size_thresholds("office")
    assert t.small_max_m2 == pytest.approx(math.sqrt(4.5 * 18.5))
    assert t.medium_max_m2 == pytest.approx(math.sqrt(18.5 * 31.3))
    assert size_thresholds("school").medium_max_m2 == pytest.approx(math.sqrt(54.8 * 102.9))


def test_elongation__rectangle_equals_its_side_ratio_and_sees_l_shapes():
    assert elongation(Room.rectangle("r", "corridor", "x", (0, 0, 20, 2))) == pytest.approx(10.0)
    assert elongation(Room.rectangle("r", "medium", "x", (0, 0, 4, 4))) == pytest.approx(1.0)
    l_shape = Room("l", "corridor", "x", [(0, 0), (12, 0), (12, 2), (2, 2), (2, 12), (0, 12)])
    assert l_shape.axes_ratio == pytest.approx(1.0)
    assert elongation(l_shape) > 10


def test_infer_labels__recovers_the_maze_office_from_shape_and_area(maze_office, strip_labels):
    inferred = infer_labels(strip_labels(maze_office))
    labels = {r.id: r.label.value for r in inferred.rooms}
    assert labels == {
        "C1": "corridor",
        "o1": "medium",
        "o2": "medium",
        "s1": "small",
        "o3": "medium",
        "o4": "medium",
        "o5": "medium",
        "C2": "medium",  # a one-door stub: shape alone cannot tell it from a room
    }
    assert labels_inferred(inferred)
    assert not labels_inferred(maze_office)


def test_infer_labels__thresholds_follow_the_building_type(maze_office, strip_labels):
    as_school = infer_labels(strip_labels(maze_office), "school")
    assert as_school.room("o1").label is SemanticLabel.SMALL


def test_infer_room_label__function_wins_over_shape():
    t = size_thresholds("office")
    lobby = Room.rectangle("h", "medium", "Lobby", (0, 0, 3, 3))
    assert infer_room_label(lobby, 1, t) is SemanticLabel.HALL
    long_office = Room.rectangle("o", "medium", "office", (0, 0, 20, 2))
    assert infer_room_label(long_office, 5, t) is SemanticLabel.BIG
    assert (
        infer_room_label(Room.rectangle("c", "big", "HALLWAY", (0, 0, 9, 9)), 1, t) is SemanticLabel.CORRIDOR
    )


def test_infer_room_label__hall_by_doors_and_corridor_by_shape():
    t = size_thresholds("office")
    square = Room.rectangle("h", "medium", "unknown", (0, 0, 10, 10))
    assert infer_room_label(square, 4, t) is SemanticLabel.HALL
    assert infer_room_label(square, 3, t) is SemanticLabel.BIG
    strip = Room.rectangle("c", "medium", "", (0, 0, 14, 2))
    assert infer_room_label(strip, 2, t) is SemanticLabel.CORRIDOR
    assert infer_room_label(strip, 1, t) is SemanticLabel.BIG
    assert infer_room_label(strip, 2, t, InferenceRules(long_corridor_min_elongation=8)) is SemanticLabel.BIG


def test_lacks_labels__single_label_or_metadata(maze_office, strip_labels):
    assert not lacks_labels(maze_office)
    assert lacks_labels(strip_labels(maze_office))
    flagged = Building("office", maze_office.rooms, maze_office.doors, {"semantic_labels": "missing"})
    assert lacks_labels(flagged)


def test_infer_labels__keeps_geometry_doors_and_metadata(maze_office):
    inferred = infer_labels(maze_office)
    assert [r.outline for r in inferred.rooms] == [r.outline for r in maze_office.rooms]
    assert inferred.doors == maze_office.doors
    assert inferred.metadata["source"] == "maze_office"
    assert isinstance(inferred.doors[0], Door)
