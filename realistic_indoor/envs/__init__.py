"""envs (work in progress)."""
