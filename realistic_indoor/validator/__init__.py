"""validator (work in progress)."""
