import math

import numpy as np

from realistic_indoor.navigation.frontiers import find_frontiers
from realistic_indoor.navigation.planning import CostConfig, clearance, costmap, dijkstra, trace_path
from realistic_indoor.sim.mapping import MAPPED_FREE, MAPPED_OCCUPIED, MAPPED_UNKNOWN


def _room(h=30, w=40):
    state = np.full((h, w), MAPPED_FREE, dtype=np.uint8)
    state[0, :] = state[-1, :] = state[:, 0] = state[:, -1] = MAPPED_OCCUPIED
    return state


def test_costmap__lethal_unknown_and_walls_expensive_near_walls():
    state = _room()
    state[10:20, 30:35] = MAPPED_UNKNOWN
    cost = costmap(state, clearance(state, 0.1), 0.1, 0.25, CostConfig())
    assert np.isinf(cost[0, 5]) and np.isinf(cost[15, 32])
    assert cost[1, 20] == CostConfig().inscribed_cost  # 0.1 m from the wall: inside the robot's radius
    assert cost[15, 15] == 1.0  # 1.4 m from every wall
    assert 1.0 < cost[4, 20] < CostConfig().inscribed_cost


def test_dijkstra__goes_around_a_wall_through_the_gap():
    state = _room()
    state[1:25, 20] = MAPPED_OCCUPIED  # a wall with a gap at rows 25-28
    cost = np.where(state == MAPPED_FREE, 1.0, np.inf)
    goals = np.zeros(state.shape, dtype=bool)
    goals[5, 30] = True
    dist, parent, goal = dijkstra(cost, (5, 10), goals, first_only=True)
    assert goal == 5 * state.shape[1] + 30
    path = trace_path(parent, goal)
    assert tuple(path[0]) == (5, 10) and tuple(path[-1]) == (5, 30)
    assert path[:, 0].max() >= 25  # through the gap
    steps = np.hypot(*np.diff(path, axis=0).T)
    assert math.isclose(steps.sum(), dist[5, 30])
    assert np.all(state[path[:, 0], path[:, 1]] == MAPPED_FREE)


def test_dijkstra__unreachable_goal_gives_minus_one():
    state = _room()
    state[:, 20] = MAPPED_OCCUPIED
    cost = np.where(state == MAPPED_FREE, 1.0, np.inf)
    goals = np.zeros(state.shape, dtype=bool)
    goals[5, 30] = True
    _, _, goal = dijkstra(cost, (5, 10), goals, first_only=False)
    assert goal == -1


def test_find_frontiers__boundary_between_free_and_unknown():
    state = np.full((20, 20), MAPPED_UNKNOWN, dtype=np.uint8)
    state[5:15, 5:15] = MAPPED_FREE
    state[5:15, 5] = MAPPED_OCCUPIED  # a wall on the west side: no frontier there
    state[2, 2] = MAPPED_FREE  # a lone free cell: too small a frontier
    f = find_frontiers(state, min_cells=3)
    assert f.count == 1
    cells = np.argwhere(f.mask)
    on_edge = (cells[:, 0] == 5) | (cells[:, 0] == 14) | (cells[:, 1] == 14)
    assert on_edge.all()
    assert f.sizes[1] == len(cells)


def test_find_frontiers__search_adds_the_unswept_floor():
    state = np.full((20, 20), MAPPED_FREE, dtype=np.uint8)
    searched = np.zeros_like(state, dtype=bool)
    searched[:, :10] = True
    assert find_frontiers(state).count == 0
    f = find_frontiers(state, searched)
    assert f.count == 1 and np.all(np.argwhere(f.mask)[:, 1] == 9)


def test_find_frontiers__small_ones_dropped_the_rest_numbered_in_scan_order():
    state = np.full((12, 20), MAPPED_OCCUPIED, dtype=np.uint8)
    state[1, 1:6] = MAPPED_FREE  # 5 cells over unknown ones: a frontier
    state[2, 1:6] = MAPPED_UNKNOWN
    state[4, 10:12] = MAPPED_FREE  # 2 cells: too small
    state[5, 10:12] = MAPPED_UNKNOWN
    state[8, 3:7] = MAPPED_FREE  # 4 cells
    state[9, 3:7] = MAPPED_UNKNOWN
    f = find_frontiers(state, min_cells=3)
    assert f.count == 2
    assert f.labels.dtype == np.int32
    assert list(f.sizes[1:]) == [5, 4]
    assert (f.labels[1, 1:6] == 1).all() and (f.labels[8, 3:7] == 2).all()
    assert f.labels[4, 10:12].tolist() == [0, 0]
    rest = f.without(f.labels == 1)
    assert rest.count == 1 and list(rest.sizes[1:]) == [4]
    assert (rest.labels[8, 3:7] == 1).all() and rest.labels.sum() == 4


def test_nearest_labels__finds_the_k_nearest_regions_in_the_order_a_full_search_ranks_them():
    from realistic_indoor.navigation.planning import nearest_labels

    rng = np.random.default_rng(0)
    cost = 1.0 + rng.random((40, 50)) * 3.0
    cost[rng.random(cost.shape) < 0.15] = np.inf  # scattered obstacles
    cost[20, 25] = 1.0
    labels = np.zeros(cost.shape, dtype=np.int32)
    for lab, (r, c) in enumerate([(2, 3), (35, 45), (10, 40), (30, 5), (20, 27), (5, 25)], start=1):
        labels[r : r + 2, c : c + 3] = lab
        cost[r : r + 2, c : c + 3] = 1.0
    dist, _, first = dijkstra(cost, (20, 25), labels > 0, first_only=False)
    flat = np.flatnonzero(labels)
    best = {}  # label -> (cost, cell): the nearest cell of each label, ties by the smaller index
    for cell in flat:
        d = dist.ravel()[cell]
        lab = int(labels.ravel()[cell])
        if np.isfinite(d) and (lab not in best or (d, cell) < best[lab]):
            best[lab] = (d, cell)
    want = sorted(best.items(), key=lambda item: item[1])
    for k in (1, 3, 10):
        _, parent, got_labels, got_cells = nearest_labels(cost, (20, 25), labels, 6, k)
        assert got_labels.tolist() == [lab for lab, _ in want[:k]]
        assert got_cells.tolist() == [cell for _, (_, cell) in want[:k]]
        path = trace_path(parent, int(got_cells[0]))
        assert tuple(path[0]) == (20, 25) and path[-1, 0] * 50 + path[-1, 1] == got_cells[0]
    assert got_cells[0] == first  # the first is the nearest-goal search's goal
