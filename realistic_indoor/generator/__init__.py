"""generator (work in progress)."""
