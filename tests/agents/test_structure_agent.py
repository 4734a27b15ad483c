import gymnasium as gym
import numpy as np
import pytest
from agent_helpers import drive, hall_and_corridor

from realistic_indoor.agents import make_agent
from realistic_indoor.agents.structure import StructureConfig
from realistic_indoor.agents.utility import UtilityConfig
from realistic_indoor.errors import ConfigError
from realistic_indoor.navigation.planning import clearance
from realistic_indoor.navigation.regions import CORRIDOR_REGION, HALL_REGION, ROOM_REGION, find_regions
from realistic_indoor.sim.mapping import MAPPED_FREE, MAPPED_OCCUPIED


def _plan_map():
    """A 7 x 8 m hall, a 2 x 16 m corridor east of it, a 4 m room south of the corridor (0.1 m cells)."""
    s = np.full((120, 260), MAPPED_OCCUPIED, dtype=np.uint8)
    s[20:100, 10:80] = MAPPED_FREE  # the hall
    s[50:70, 80:241] = MAPPED_FREE  # the corridor, open to the hall over its whole width
    s[5:45, 140:180] = MAPPED_FREE  # the room
    s[45:50, 155:164] = MAPPED_FREE  # its 0.9 m door onto the corridor
    return s


def test_find_regions__doors_split_rooms_from_the_circulation():
    state = _plan_map()
    regions = find_regions(state, clearance(state, 0.1), 0.1)
    hall, corridor, room = regions.labels[60, 40], regions.labels[60, 200], regions.labels[25, 160]
    assert hall == corridor  # a wide opening joins them
    assert room != corridor and room > 0
    assert regions.kinds[room] == ROOM_REGION
    assert regions.kinds[corridor] in (CORRIDOR_REGION, HALL_REGION)


def test_find_regions__a_lone_corridor_is_long_and_thin_a_square_hall_is_wide():
    state = np.full((140, 200), MAPPED_OCCUPIED, dtype=np.uint8)
    state[10:30, 10:190] = MAPPED_FREE  # 2 x 18 m
    state[50:130, 20:100] = MAPPED_FREE  # 8 x 8 m
    regions = find_regions(state, clearance(state, 0.1), 0.1)
    corridor, hall = regions.labels[20, 100], regions.labels[90, 60]
    assert regions.kinds[corridor] == CORRIDOR_REGION and regions.kinds[hall] == HALL_REGION
    assert regions.length_m[corridor] == pytest.approx(17.0, abs=0.2)  # 18 m less the 0.5 m margins
    assert regions.width_m[corridor] == pytest.approx(1.0, abs=0.1)


def test_find_regions__a_diagonal_corridor_is_measured_along_its_own_axis():
    # a band 2.83 m wide (20 cells either side of the diagonal, 0.1 m cells) and 19.8 m long; the
    # core leaves out 0.55 m along each wall and each end: about 1.7 x 18.7 m
    state = np.full((200, 200), MAPPED_OCCUPIED, dtype=np.uint8)
    r, c = np.mgrid[:200, :200]
    state[(np.abs(r - c) <= 20) & (r + c >= 60) & (r + c <= 340)] = MAPPED_FREE
    regions = find_regions(state, clearance(state, 0.1), 0.1)
    corridor = regions.labels[100, 100]
    assert regions.count == 1 and regions.kinds[corridor] == CORRIDOR_REGION
    assert regions.length_m[corridor] == pytest.approx(18.7, abs=0.3)
    assert regions.width_m[corridor] == pytest.approx(1.75, abs=0.25)


@pytest.mark.parametrize("name", ["utility", "structure"])
def test_map_explorers__cover_a_hand_made_office(name, hall_office):
    env = gym.make("OfficeExplore-v0", building=hall_office, max_steps=600, max_episode_steps=600)
    _, info = drive(env, make_agent(name, env))
    assert info["coverage"] >= 0.9


def _first_room_entered(name: str) -> float:
    """Where (x, m) an agent first enters a room of a hall-and-corridor office (corridor x 8-32)."""
    env = gym.make("OfficeExplore-v0", building=hall_and_corridor(6), max_steps=800, max_episode_steps=800)
    _, info = drive(env, make_agent(name, env))
    assert info["coverage"] >= 0.9
    xy = np.array(env.unwrapped.simulation.trajectory)
    in_room = (xy[:, 0] > 8.3) & ((xy[:, 1] < 2.9) | (xy[:, 1] > 5.1))
    return float(xy[np.argmax(in_room), 0])


def test_structure_agent__goes_down_the_corridor_before_entering_rooms():
    assert _first_room_entered("structure") > 24.0  # one of the last rooms
    assert _first_room_entered("frontier") < 16.0  # the nearest frontier: the first doorway


def test_configs__reject_bad_values():
    with pytest.raises(ConfigError, match="room_factor"):
        StructureConfig(room_factor=0.5)
    with pytest.raises(ConfigError, match="gain must be one of"):
        UtilityConfig(gain="entropy")
