"""The shared vocabulary: functional labels, core functions, the outside node."""

from realistic_indoor.building import Building, Door, Room
from realistic_indoor.building.labels import OUTSIDE, is_core_function, labels_inferred, normalise_function


def test_normalise_function__one_spelling_for_case_separators_and_spaces():
    assert normalise_function("  SHARED_OFFICE ") == "shared office"
    assert normalise_function("Conference   Room") == "conference room"
    assert normalise_function("open-plan office") == "open plan office"
    assert normalise_function("Open_Plan-Office") == normalise_function("open plan office")


def test_is_core_function__normalises_case_and_separators():
    assert is_core_function("Shared_Office", "office")
    assert is_core_function("CLASSROOM", "school")
    assert is_core_function("Bed-Room", "house")
    assert not is_core_function("classroom", "office")
    assert not is_core_function("office", "unknown")


def _one_room(metadata):
    room = Room("r", "medium", "office", ((0, 0), (4, 0), (4, 3), (0, 3)))
    door = Door("d", "r", None, 2.0, 0.0, 0.9, 0.0)
    return Building("office", (room,), (door,), metadata)


def test_outside__is_the_graph_node_behind_exterior_doors():
    graph = _one_room({}).graph(include_outside=True)
    assert set(graph.nodes) == {"r", OUTSIDE}
    assert list(graph.edges(OUTSIDE, keys=True)) == [(OUTSIDE, "r", "d")]


def test_labels_inferred__reads_the_metadata_marker():
    assert labels_inferred(_one_room({"semantic_labels": "inferred"}))
    assert not labels_inferred(_one_room({}))
