"""A live view of an episode: the top view in a pygame window (``render_mode="human"``).

pygame is optional: the ``viz`` extra installs it (``pip install "realistic-indoor[viz]"``), and
it is imported only when the first window opens.
"""

from __future__ import annotations

import os
from types import ModuleType

import numpy as np
from gymnasium.error import DependencyNotInstalled

__all__ = ["MIN_SIDE_PX", "Window", "upscaled"]

MIN_SIDE_PX = 512
"""Smallest longest side of the window (pixels): smaller frames are enlarged by a whole factor."""


def _import_pygame() -> ModuleType:
    os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
    try:
        import pygame
    except ImportError as error:
        raise DependencyNotInstalled(
            'render_mode="human" needs pygame, which is not installed; '
            'install it with: pip install "realistic-indoor[viz]"'
        ) from error
    return pygame


def upscaled(frame: np.ndarray) -> np.ndarray:
    """``frame`` enlarged by the whole factor that brings its longest side to ``MIN_SIDE_PX`` or more.

    Args:
        frame: An ``(H, W, 3)`` uint8 image.

    Returns:
        The ``(k H, k W, 3)`` image, each pixel a ``k`` by ``k`` square (``frame`` itself if
        ``k`` is 1).
    """
    k = max(1, MIN_SIDE_PX // max(frame.shape[:2]))
    return frame if k == 1 else frame.repeat(k, axis=0).repeat(k, axis=1)


class Window:
    """A pygame window showing frames, no faster than a frame rate.

    The window takes the size of the (enlarged, see :func:`upscaled`) frame and follows it when
    the building changes. Without a display (a server, CI) set ``SDL_VIDEODRIVER=dummy``.

    Args:
        title: The window's caption.
        fps: Most frames per second; :meth:`show` waits so that frames come no faster (the
            environment then runs in real time). ``0`` does not wait.

    Raises:
        DependencyNotInstalled: If pygame is not installed (it names the extra to install).
    """

    def __init__(self, title: str, fps: float) -> None:
        self._pygame = _import_pygame()
        self._pygame.display.init()
        self._pygame.display.set_caption(title)
        self._clock = self._pygame.time.Clock()
        self._fps = fps
        self._screen = None

    @property
    def is_open(self) -> bool:
        """Whether the window is open (it opens with the first frame)."""
        return self._screen is not None

    def show(self, frame: np.ndarray) -> None:
        """Draw an ``(H, W, 3)`` uint8 frame, then wait for the frame rate.

        Args:
            frame: The image, row 0 at the top.
        """
        pygame = self._pygame
        image = upscaled(frame)
        size = (image.shape[1], image.shape[0])
        if self._screen is None or self._screen.get_size() != size:
            self._screen = pygame.display.set_mode(size)
        self._screen.blit(pygame.surfarray.make_surface(image.swapaxes(0, 1)), (0, 0))
        pygame.event.pump()  # keep the window responsive
        pygame.display.flip()
        if self._fps:
            self._clock.tick(self._fps)

    def close(self) -> None:
        """Close the window and shut pygame down (harmless if already closed)."""
        self._pygame.display.quit()
        self._pygame.quit()
        self._screen = None
