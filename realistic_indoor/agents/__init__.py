"""agents (work in progress)."""
