"""Weighted draws that consume the random stream exactly as NumPy's ``Generator.choice`` does."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from collections.abc import Sequence

    import numpy as np

__all__ = ["choice_index"]


def choice_index(rng: np.random.Generator, p: Sequence[float]) -> int:
    """An index ``i`` drawn with probability ``p[i]``: what ``rng.choice(len(p), p=p)`` returns.

    NumPy's ``choice`` spends most of its 4-5 microseconds converting and checking ``p``. This
    draws the same single ``rng.random()`` and finds the index the way ``choice`` does (the
    running sums of ``p``, each divided by the last, and the first of them above the draw), so
    it returns the same index from the same state and leaves the generator in the same state:
    buildings stay the same to the byte. About 0.7 microseconds for a few weights.

    Args:
        rng: Random source; one uniform draw is taken from it.
        p: Non-negative probabilities with a positive sum, normally summing to 1 (not checked).

    Returns:
        The drawn index, ``0 <= i < len(p)``.
    """
    u = rng.random()
    running, sums = 0.0, []
    for x in p:
        running += x
        sums.append(running)
    last = sums[-1]
    for i, s in enumerate(sums):
        if s / last > u:
            return i
    return len(sums) - 1  # not reached: the last sum over itself is 1 and the draw is below 1
