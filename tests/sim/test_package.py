import subprocess
import sys

import realistic_indoor.sim as sim


def test_sim__every_public_name_resolves():
    for name in sim.__all__:
        assert getattr(sim, name) is not None
    assert set(dir(sim)) == set(sim.__all__)


def test_sim__raster_alone_does_not_load_numba_or_pymunk():
    code = "import sys, realistic_indoor.sim.raster; print('numba' in sys.modules, 'pymunk' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["False", "False"]
