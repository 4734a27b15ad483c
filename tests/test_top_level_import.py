import subprocess
import sys


def _run(code: str) -> str:
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return out.stdout.strip()


def test_import__registers_env_ids_without_loading_the_simulator():
    code = (
        "import sys, gymnasium as gym, realistic_indoor\n"
        "print('OfficeExplore-v0' in gym.registry, 'RandomSearch-v0' in gym.registry)\n"
        "print(any(m in sys.modules for m in ('numba', 'pymunk', 'torch', 'matplotlib', 'shapely')))"
    )
    assert _run(code).splitlines() == ["True True", "False"]


def test_import__lazy_names_resolve():
    import realistic_indoor

    assert callable(realistic_indoor.generate)
    assert realistic_indoor.Building.__name__ == "Building"
