"""sim (work in progress)."""
