"""Which module reads and writes which file format, chosen from the file name."""

from __future__ import annotations

import importlib
import inspect
from pathlib import Path
from typing import TYPE_CHECKING, Any

from realistic_indoor.building.admit import admit_building
from realistic_indoor.errors import ConfigError, PlanFormatError, RealisticIndoorError
from realistic_indoor.files import check_output_path

if TYPE_CHECKING:
    from realistic_indoor.building.building import Building

__all__ = ["FORMATS", "MAX_PLAN_BYTES", "READABLE", "WRITABLE", "format_of", "load", "save"]

# name: (file endings, module under realistic_indoor.io, can read, can write)
FORMATS: dict[str, tuple[tuple[str, ...], str, bool, bool]] = {
    "json": ((".json",), "json_format", True, True),
    "worldgen": ((".wg.xml",), "worldgen", True, True),
    "floorplan": ((".xml",), "floorplan_xml", True, True),
    "ros": ((".yaml", ".pgm"), "ros_map", False, True),
    "png": ((".png",), "render", False, True),
    "svg": ((".svg",), "render", False, True),
    "sdf": ((".sdf", ".world"), "world3d.sdf", False, True),
    "mjcf": ((".mjcf.xml",), "world3d.mjcf", False, True),
    "glb": ((".glb",), "world3d.gltf", False, True),
    "obj": ((".obj",), "world3d.obj", False, True),
}
MAX_PLAN_BYTES = 256 * 1024 * 1024
"""Largest plan file :func:`load` reads (bytes); the largest shared real plan has 0.5 MB."""
READABLE = tuple(k for k, v in FORMATS.items() if v[2])
WRITABLE = tuple(k for k, v in FORMATS.items() if v[3])


def format_of(path: str | Path, fmt: str | None = None) -> str:
    """The format name of ``path`` from its ending (longest match), or ``fmt`` if given.

    Raises:
        RealisticIndoorError: If the ending is unknown; the message lists the known ones.
    """
    if fmt is not None:
        if fmt not in FORMATS:
            raise RealisticIndoorError(f"unknown format {fmt!r}; known formats: {', '.join(FORMATS)}")
        return fmt
    name = Path(path).name.lower()
    matches = [(len(e), f) for f, (ends, *_rest) in FORMATS.items() for e in ends if name.endswith(e)]
    if not matches:
        ends = ", ".join(e for ends, *_ in FORMATS.values() for e in ends)
        raise RealisticIndoorError(f"{path}: cannot tell the format from the file name; use one of {ends}")
    return max(matches)[1]


def _module(fmt: str):
    return importlib.import_module(f"realistic_indoor.io.{FORMATS[fmt][1]}")


def load(path: str | Path, fmt: str | None = None, *, strict: bool = False, **options: Any) -> Building:
    """Read a building from ``path``; the format comes from the ending unless ``fmt`` is given.

    A ``.xml`` file whose root element is ``<world>`` is read as World Generator XML. Every
    plan passes :func:`~realistic_indoor.building.admit.admit_building` (finite coordinates
    within a plausible extent, valid outlines, doors naming existing rooms, at least one room),
    which refuses what cannot be used and repairs a self-crossing outline with a warning.

    Args:
        path: The file.
        fmt: A format name of :data:`FORMATS`, to override the one the ending gives.
        strict: Refuse a plan that needs a repair (raise) instead of repairing it with a
            ``PlanRepairWarning``: in floor-plan XML, portals or outlines that contradict each
            other; in any format, an outline that crosses itself.
        **options: Passed to the format's reader (e.g. ``infer_entrances=True``).

    Raises:
        PlanFormatError: If the file is missing, unreadable, larger than
            :data:`MAX_PLAN_BYTES`, malformed, refused by the gate, or, with ``strict``, has a
            defect that would be repaired.
    """
    path = Path(path)
    if not path.is_file():
        raise PlanFormatError(path, "no such file" if not path.exists() else "not a file")
    size = path.stat().st_size
    if size > MAX_PLAN_BYTES:
        raise PlanFormatError(
            path, f"{size:,} bytes; plan files of at most {MAX_PLAN_BYTES:,} bytes are read"
        )
    fmt = format_of(path, fmt)
    if fmt == "floorplan" and _root_tag(path) == "world":
        fmt = "worldgen"
    if not FORMATS[fmt][2]:
        raise PlanFormatError(
            path, f"{fmt} files can be written but not read; readable: {', '.join(READABLE)}"
        )
    if strict and fmt == "floorplan":
        options["strict"] = True
    reader = _module(fmt).read
    try:
        inspect.signature(reader).bind(path, **options)
    except TypeError:
        known = [k for k in inspect.signature(reader).parameters if k != "path"]
        raise ConfigError(
            f"{fmt} plans take no option {', '.join(sorted(set(options) - set(known)))}; "
            f"their options: {', '.join(known) or 'none'}"
        ) from None
    return admit_building(reader(path, **options), path, strict=strict)


def save(building: Building, path: str | Path, fmt: str | None = None, **options: Any) -> list[Path]:
    """Write ``building`` to ``path`` in the format its ending names (or ``fmt``).

    The file is written whole or not at all: a failed write leaves a previous file intact.

    Returns:
        The files written (a ROS map writes an image and a YAML file).

    Raises:
        RealisticIndoorError: If the format is unknown, ``path`` is a folder or its folder
            cannot be written.
    """
    fmt = format_of(path, fmt)
    path = check_output_path(path, "output")
    written = _module(fmt).write(building, path, **options)
    return list(written) if written else [path]


def _root_tag(path: Path) -> str | None:
    """The first element's tag, read cheaply (``None`` if it cannot be found)."""
    import re

    try:
        with open(path, "rb") as f:
            head = f.read(4096).decode("utf-8", "replace")
    except OSError as e:
        raise PlanFormatError(path, f"cannot read the file ({e.strerror or e})") from None
    m = re.search(r"<\s*([A-Za-z_][\w.-]*)", re.sub(r"<\?.*?\?>|<!--.*?-->", "", head, flags=re.S))
    return m.group(1) if m else None
