"""The hypothesis settings every fuzz test shares: derandomised (CI sees the same examples each
run), no example database, no deadline (the first example pays for imports)."""

from hypothesis import HealthCheck, settings


def fuzz(examples: int) -> settings:
    """Settings for a fuzz test of ``examples`` examples."""
    return settings(
        derandomize=True,
        max_examples=examples,
        deadline=None,
        suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
        database=None,
    )
