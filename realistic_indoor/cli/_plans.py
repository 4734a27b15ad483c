"""Helpers shared by the subcommands that read one plan."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from realistic_indoor.errors import ConfigError

if TYPE_CHECKING:
    from realistic_indoor.building import Building


def add_plan_options(parser: argparse.ArgumentParser) -> None:
    """Add the options of reading a plan: ``--infer-entrances`` and ``--strict``.

    ``--strict`` is added only once, so a subcommand that has its own may keep it
    (:func:`load_plan` reads ``args.strict`` either way).
    """
    parser.add_argument(
        "--infer-entrances",
        action="store_true",
        help="floor-plan XML input: add exterior doors where the plan's entrances are (real plans have none)",
    )
    if "--strict" not in parser._option_string_actions:
        parser.add_argument(
            "--strict",
            action="store_true",
            help="floor-plan XML input: refuse a plan whose portals or room outlines contradict each "
            "other instead of repairing it with a warning",
        )


add_infer_entrances = add_plan_options
"""The name ``convert`` and ``render`` use; it adds ``--strict`` too."""


def load_plan(args: argparse.Namespace) -> Building:
    """Read ``args.plan``, inferring entrances and refusing repairs as the flags say.

    Raises:
        ConfigError: If ``--infer-entrances`` is given for a plan that is not floor-plan XML.
        PlanFormatError: If the plan cannot be read, or with ``--strict`` needs a repair.
    """
    from realistic_indoor.io import format_of, load

    strict = bool(getattr(args, "strict", False))
    if not getattr(args, "infer_entrances", False):
        return load(args.plan, strict=strict)
    if format_of(args.plan) != "floorplan":
        raise ConfigError(f"{args.plan}: --infer-entrances applies to floor-plan XML plans only")
    return load(args.plan, strict=strict, infer_entrances=True)
