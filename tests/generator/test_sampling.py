"""choice_index against NumPy's Generator.choice: the same index from the same state."""

import numpy as np
import pytest

from realistic_indoor.generator.sampling import choice_index


@pytest.mark.parametrize("seed", range(40))
def test_choice_index__returns_numpys_index_and_leaves_the_same_state(seed):
    setup = np.random.default_rng(seed)
    n = int(setup.integers(1, 9))
    weights = setup.random(n) * setup.integers(1, 100)
    weights[setup.random(n) < 0.25] = 0.0  # zero weights: never drawn, as in numpy
    if weights.sum() == 0:
        weights[0] = 1.0
    p = [w / weights.sum() for w in weights.tolist()]
    ours, numpys = np.random.default_rng(1000 + seed), np.random.default_rng(1000 + seed)
    drawn = [choice_index(ours, p) for _ in range(200)]
    assert drawn == [int(numpys.choice(n, p=p)) for _ in range(200)]
    assert ours.random() == numpys.random()  # one draw each: the streams stay together
    assert all(p[i] > 0 for i in drawn)


def test_choice_index__follows_the_weights():
    rng = np.random.default_rng(0)
    counts = np.bincount([choice_index(rng, (0.45, 0.3, 0.15, 0.1)) for _ in range(20_000)], minlength=4)
    assert np.allclose(counts / 20_000, (0.45, 0.3, 0.15, 0.1), atol=0.015)
