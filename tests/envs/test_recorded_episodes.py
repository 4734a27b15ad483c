"""Episodes are the same as when they were recorded (before the one-home refactor, issue 16).

Each case is made with the ``gym.make`` keywords of that time and replayed with the same seeds
and actions; the rewards, episode ends and a digest of every observation and ``info`` must match
the recording byte for byte. Regenerate with ``python tests/envs/recorded_episodes.py`` only when
a change is meant to alter episodes, and say so in the commit.
"""

from __future__ import annotations

import json

import pytest
from recorded_episodes import CASES, DATA, VECTOR_CASE, run_case, run_vector_case

RECORDED = json.loads(DATA.read_text())


@pytest.mark.parametrize("name", sorted(CASES))
def test_episode__replays_its_recording(name):
    got = run_case(CASES[name])
    want = RECORDED[name]
    assert got["rewards"] == want["rewards"]
    assert got["ends"] == want["ends"]
    assert got["victim_steps"] == want["victim_steps"]
    assert got["digest"] == want["digest"]


def test_recording__finds_victims_and_ends_an_episode():
    """The recording exercises victim rewards and termination, not only empty steps."""
    case = RECORDED["victims-beside-start"]
    assert case["victim_steps"] > 0
    assert any(terminated for terminated, _ in case["ends"])
    assert any(float(r) > 4.0 for r in case["rewards"])


def test_vector_episode__replays_its_recording():
    got = run_vector_case(VECTOR_CASE)
    assert got == RECORDED["vector"]
