"""The map-based explorers take the actions they took when recorded (``recorded_explorers.py``).

Moving their map, planner, follower and reflexes to another package (or making them faster) must
not change a single action: a digest of every action of 300-step episodes in four environments
(continuous and discrete actions, exploration and search) is compared with the recording.
"""

from __future__ import annotations

import json

import pytest
from recorded_explorers import AGENT_NAMES, DATA, ENV_CASES, run_case

RECORDED = json.loads(DATA.read_text())


@pytest.mark.parametrize("agent", AGENT_NAMES)
@pytest.mark.parametrize("case", sorted(ENV_CASES))
def test_explorer_episode__replays_its_recording(agent, case):
    assert run_case(agent, ENV_CASES[case]) == RECORDED[f"{agent}/{case}"]


def test_recording__explorers_make_progress():
    """The recording is of explorers at work, not of robots standing still."""
    for key, value in RECORDED.items():
        assert float(value["coverage"]) > 0.1, key
