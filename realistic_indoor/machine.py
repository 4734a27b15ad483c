"""What the figures a run reports depend on: the processor, its cores and the load."""

from __future__ import annotations

import os
import platform
from pathlib import Path

__all__ = ["describe_machine"]


def describe_machine(load: bool = True) -> str:
    """The CPU model and logical cores, and (with ``load``) the load average over 1, 5 and 15 min.

    >>> "logical cores" in describe_machine(load=False)
    True
    """
    model = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    text = f"{model}, {os.cpu_count()} logical cores"
    if load and hasattr(os, "getloadavg"):
        text += ", load average " + ", ".join(f"{x:.1f}" for x in os.getloadavg()) + " (1, 5, 15 min)"
    return text
