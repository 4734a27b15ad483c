"""Doors the generator adds last: a second way out of room mazes, none out of a room's service rooms."""

import numpy as np
import pytest

from realistic_indoor.building.labels import SemanticLabel
from realistic_indoor.generator.connect import break_mazes
from realistic_indoor.generator.doors import RULES, add_door
from realistic_indoor.generator.geometry import to_units
from realistic_indoor.generator.plan import Plan, PlanRoom
from realistic_indoor.generator.rooms.annex import expected_service_rooms

C, B, S = SemanticLabel.CORRIDOR, SemanticLabel.BIG, SemanticLabel.SMALL


def _gym_with_two_rooms_behind(hosted: bool) -> Plan:
    """A corridor, a 20 x 15 m room on it, two 10 x 4 m rooms behind the room on the facade.

    The back rooms open only into the big room, so the three are a maze by the validator's
    definition (three ordinary rooms, one of which opens onto circulation).
    """
    u = to_units
    plan = Plan()
    corridor = plan.add(PlanRoom([(0, 0, u(20.0), u(2.0))], C, role="corridor"))
    gym = plan.add(PlanRoom([(0, u(2.0), u(20.0), u(17.0))], B, role="annex"))
    host = gym if hosted else -1
    backs = [
        plan.add(PlanRoom([(u(x), u(17.0), u(x + 10.0), u(21.0))], S, role="closet", host=host))
        for x in (0.0, 10.0)
    ]
    for a, b in [(corridor, gym), *((gym, k) for k in backs)]:
        assert add_door(plan, a, b, plan.shared(a, b)[0], RULES.room, where="centre")
    return plan


def _exterior_doors(plan: Plan) -> list[int]:
    return [d.a for d in plan.doors if d.b is None]


def test_break_mazes__a_big_rooms_own_service_rooms_get_no_door_to_the_outside():
    plan = _gym_with_two_rooms_behind(hosted=True)
    before = len(plan.doors)
    break_mazes(plan, np.random.default_rng(0))
    assert len(plan.doors) == before


def test_break_mazes__rooms_behind_a_room_that_are_not_its_own_get_one_way_out():
    plan = _gym_with_two_rooms_behind(hosted=False)
    break_mazes(plan, np.random.default_rng(0))
    exits = _exterior_doors(plan)
    assert len(exits) == 1
    assert plan.rooms[exits[0]].label is S


@pytest.mark.parametrize(
    ("area_m2", "expected"),
    [
        # sides sqrt(600 * 1.6) = 31.0 m and sqrt(600 / 1.6) = 19.4 m: 4 and 2 rooms of 7 m
        (600.0, 3.0),
        # sides 12.6 and 7.9 m: 1 room each, raised to the least of 2
        (100.0, 2.0),
        # sides 40.0 and 25.0 m: 5 and 3 rooms
        (1000.0, 4.0),
    ],
)
def test_expected_service_rooms__rooms_of_7_m_along_either_side_of_the_annex(area_m2, expected):
    assert expected_service_rooms(area_m2, ((3.4, 4.6), 7.0)) == expected
