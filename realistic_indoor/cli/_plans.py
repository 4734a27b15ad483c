"""Helpers shared by the subcommands that read one plan."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from realistic_indoor.building import Building


def add_infer_entrances(parser: argparse.ArgumentParser) -> None:
    """Add the ``--infer-entrances`` flag (floor-plan XML only)."""
    parser.add_argument(
        "--infer-entrances",
        action="store_true",
        help="floor-plan XML input: add exterior doors where the plan's entrances are (real plans have none)",
    )


def load_plan(args: argparse.Namespace) -> Building:
    """Read ``args.plan``, inferring entrances when ``--infer-entrances`` was given.

    Raises:
        ConfigError: If ``--infer-entrances`` is given for a plan that is not floor-plan XML.
    """
    from realistic_indoor.io import format_of, load

    if not getattr(args, "infer_entrances", False):
        return load(args.plan)
    if format_of(args.plan) != "floorplan":
        raise ConfigError(f"{args.plan}: --infer-entrances applies to floor-plan XML plans only")
    return load(args.plan, infer_entrances=True)
