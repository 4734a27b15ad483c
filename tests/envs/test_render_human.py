"""render_mode="human": the top view in a pygame window, headless with SDL's dummy video driver."""

from __future__ import annotations

import pickle
import sys

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.error import DependencyNotInstalled

import realistic_indoor.envs  # noqa: F401  (registers the ids)
from realistic_indoor.envs import ExploreEnv
from realistic_indoor.envs.window import MIN_SIDE_PX

FORWARD = np.array([1.0, 0.3], np.float32)


@pytest.fixture
def pygame(monkeypatch):
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")  # before the window initialises the display
    return pytest.importorskip("pygame", reason="render_mode='human' needs pygame (the viz extra)")


def _shown(pygame) -> np.ndarray:
    """The window's pixels as an ``(H, W, 3)`` image."""
    return pygame.surfarray.array3d(pygame.display.get_surface()).swapaxes(0, 1)


def test_human__is_a_declared_render_mode_at_the_control_rate(toy_building):
    env = gym.make("OfficeExplore-v0", building=toy_building, render_mode="human")
    assert env.unwrapped.render_mode == "human"  # not gym.make's HumanRendering fallback
    assert "human" in env.metadata["render_modes"] and "rgb_array" in env.metadata["render_modes"]
    assert env.metadata["render_fps"] == 5  # robot.control_hz


def test_human__window_shows_the_rgb_frame_and_close_closes_it(pygame, toy_building):
    human = gym.make("OfficeSearch-v0", building=toy_building, render_mode="human")
    twin = gym.make("OfficeSearch-v0", building=toy_building, render_mode="rgb_array")
    human.reset(seed=0)
    twin.reset(seed=0)
    assert pygame.display.get_init() and pygame.display.get_caption()[0].endswith("OfficeSearch-v0")
    for _ in range(3):
        human.step(FORWARD)
        twin.step(FORWARD)
    assert human.render() is None
    frame = twin.render()
    k = MIN_SIDE_PX // max(frame.shape[:2])  # a 10 m wide toy: enlarged by a whole factor
    assert k >= 2
    np.testing.assert_array_equal(_shown(pygame), frame.repeat(k, axis=0).repeat(k, axis=1))
    human.close()
    assert not pygame.display.get_init()
    human.close()  # twice is harmless


def test_human__pickled_env_leaves_the_window_behind(pygame, toy_building):
    env = ExploreEnv(building=toy_building, render_mode="human")
    env.reset(seed=0)
    copy = pickle.loads(pickle.dumps(env))
    assert copy.simulation.robot.pose == env.simulation.robot.pose
    env.close()
    copy.close()


def test_human__without_pygame_names_the_extra(monkeypatch, toy_building):
    monkeypatch.setitem(sys.modules, "pygame", None)  # import pygame now raises ImportError
    env = ExploreEnv(building=toy_building, render_mode="human")
    with pytest.raises(DependencyNotInstalled, match=r"pip install \"realistic-indoor\[viz\]\""):
        env.reset(seed=0)
    env.close()
