"""``realistic-indoor generate``: realistic offices, schools and houses, or random baseline maps."""

from __future__ import annotations

import argparse
from pathlib import Path

from realistic_indoor.cli._like import add_like_options, run_like
from realistic_indoor.cli._outputs import add_overwrite_option
from realistic_indoor.cli._world3d import add_world_options, save_options


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``generate`` subcommand."""
    from realistic_indoor.generator import DEFAULT_AREAS_M2, GENERATOR_NAMES

    defaults = ", ".join(f"{k} {v:g}" for k, v in DEFAULT_AREAS_M2.items())
    p = sub.add_parser(
        "generate",
        help="generate buildings of a type (office, school, house) or random baseline maps",
        description="Generate a building of a type whose statistics match real buildings of that "
        "type, or a random World-Generator-like map. You choose the floor area, never width and "
        "height: the footprint's proportions come out of the layout. Output formats follow the "
        "file extension (.json, .xml, .wg.xml, .yaml, .png, .svg; 3D worlds .sdf, .world, "
        ".mjcf.xml, .glb, .obj).",
        epilog="examples:\n"
        "  realistic-indoor generate --type school --area 3000 --seed 7 -o school.json --png school.png\n"
        "  realistic-indoor generate --type office --count 200 --out-dir maps/\n"
        "  realistic-indoor generate --type random --width 17 --height 13 -o random.wg.xml\n"
        "  realistic-indoor generate --type office --seed 7 -o office.sdf   # a Gazebo world\n"
        "  realistic-indoor generate --type office --like real/offices/ --out-dir twins/   # same areas",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--type", default="office", choices=GENERATOR_NAMES, help="building type (default office)")
    p.add_argument("--area", type=float, help=f"floor area in m2 (defaults: {defaults})")
    p.add_argument(
        "--seed", type=int, help="random seed (default: a fresh one, printed); first seed with --count"
    )
    p.add_argument("-o", "--output", help="file to write; its extension picks the format")
    p.add_argument("--png", help="also draw the building to this picture (.png or .svg; not with --count)")
    p.add_argument("--count", type=int, help="generate this many buildings (seeds seed, seed+1, ...)")
    p.add_argument("--out-dir", help="folder for --count buildings, named TYPE_SEED.EXT")
    p.add_argument(
        "--format",
        default="json",
        help="extension of the --count files: json, xml, wg.xml, png, ... (default json)",
    )
    p.add_argument(
        "--model",
        help="offices and schools: 'real' (default: fitted to real plans), 'paper' (Table 1, wing layout) "
        "or a JSON file of a fitted building-type model (see fit_model)",
    )
    p.add_argument(
        "--layout",
        choices=("blocks", "wings"),
        help="offices and schools: compact blocks (default) or wings (default with --model paper)",
    )
    p.add_argument("--width", type=int, help="random maps: grid width in 3 m cells (with --height)")
    p.add_argument("--height", type=int, help="random maps: grid height in 3 m cells (with --width)")
    add_like_options(p)
    add_world_options(p)
    add_overwrite_option(p, "output files")
    p.set_defaults(func=run)


def _generator(args: argparse.Namespace):
    from realistic_indoor.generator import make_generator

    return make_generator(args.type, args.area, **_options(args))


def _options(args: argparse.Namespace) -> dict:
    """The generator's options from ``--width``/``--height`` and ``--model``."""
    from realistic_indoor.errors import ConfigError

    options = {}
    if args.width is not None or args.height is not None:
        if args.type != "random" or args.width is None or args.height is None:
            raise ConfigError("--width and --height go together, and only with --type random")
        _check_grid_size(args.width, args.height)
        options = {"width_units": args.width, "height_units": args.height}
    if args.model:
        if args.type == "random":
            raise ConfigError("--model drives the realistic generators, not --type random")
        named = args.model in ("real", "paper") and args.type in ("office", "school")
        options["model"] = args.model if named else _read_model(Path(args.model))
    if getattr(args, "layout", None):
        if args.type not in ("office", "school"):
            raise ConfigError(
                f"--layout chooses how offices and schools are laid out, not --type {args.type}"
            )
        options["layout"] = args.layout
    return options


def _check_grid_size(width: int, height: int) -> None:
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.generator.random_grid import CELL_M, MAX_UNITS, MIN_UNITS

    for option, value in (("--width", width), ("--height", height)):
        if not MIN_UNITS <= value <= MAX_UNITS:
            raise ConfigError(
                f"{option} counts {CELL_M:g} m grid cells, from {MIN_UNITS} to {MAX_UNITS}; got {value}"
            )


def _model_file(args: argparse.Namespace) -> list[str]:
    """The model file ``--model`` names, as the command's inputs (none for ``real`` or ``paper``)."""
    return [args.model] if args.model and args.model not in ("real", "paper") else []


def _read_model(path: Path):
    import json

    from realistic_indoor.errors import ConfigError
    from realistic_indoor.models import BuildingTypeModel

    try:
        return BuildingTypeModel.from_dict(json.loads(path.read_text(encoding="utf-8")))
    except OSError as e:
        raise ConfigError(f"{path}: cannot read the model ({e.strerror or e})") from None
    except UnicodeDecodeError:
        raise ConfigError(f"{path}: the model is not UTF-8 text; a model is a JSON file") from None
    except (json.JSONDecodeError, RecursionError) as e:
        raise ConfigError(f"{path}: the model is not valid JSON ({e})") from None
    except ValueError as e:
        if isinstance(e, ConfigError):
            raise ConfigError(f"{path}: {e}") from None
        raise ConfigError(f"{path}: the model holds an invalid number ({e})") from None


def run(args: argparse.Namespace) -> int:
    """Generate one building (or ``--count`` of them) and write them."""
    from realistic_indoor.errors import ConfigError

    if args.like:
        return run_like(args, _options(args))
    gen = _generator(args)
    if args.count is None:
        if args.out_dir:
            raise ConfigError("--out-dir goes with --count; for one building use -o FILE")
        _check_outputs(args)
        return _one(gen, args)
    if args.count < 1:
        raise ConfigError(f"--count must be at least 1, not {args.count}")
    if not args.out_dir or args.output:
        raise ConfigError("--count writes one file per building into --out-dir DIR (not -o)")
    return _many(gen, args)


def _check_outputs(args: argparse.Namespace) -> None:
    """Refuse unwritable, existing (without ``--overwrite``) or input ``-o`` and ``--png`` paths first."""
    from realistic_indoor.cli._outputs import check_output
    from realistic_indoor.errors import ConfigError

    inputs = _model_file(args)
    if args.output:
        save_options(args, args.output)
        check_output(args.output, "-o", overwrite=args.overwrite, inputs=inputs)
    if args.png:
        check_output(args.png, "--png", overwrite=args.overwrite, inputs=inputs, suffixes=(".png", ".svg"))
    if args.output and args.png and Path(args.output).resolve() == Path(args.png).resolve():
        raise ConfigError(f"-o and --png name the same file {args.output}; give them different names")


def _one(gen, args: argparse.Namespace) -> int:
    from realistic_indoor.generator import generate_from
    from realistic_indoor.io import save

    b = generate_from(gen, args.seed)
    print(f"{args.type}, seed {b.metadata['seed']}")
    print(b.summary())
    for target, options in ((args.output, True), (args.png, False)):
        if target:
            for path in save(b, target, **(save_options(args, target) if options else {})):
                print(f"wrote {path}")
    return 0


def _many(gen, args: argparse.Namespace) -> int:
    from tqdm import tqdm

    from realistic_indoor.cli._outputs import check_new_outputs, companions
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.files import check_output_dir
    from realistic_indoor.generator import generate_from
    from realistic_indoor.io import save

    if args.png:
        raise ConfigError("--png draws one building; with --count use --format png (or svg) for pictures")
    out = check_output_dir(args.out_dir, "--out-dir")
    ext = "." + args.format.lstrip(".")
    options = save_options(args, f"x{ext}")
    first = args.seed if args.seed is not None else 0
    if first < 0:
        raise ConfigError(f"--seed must be a non-negative integer, not {first}")
    seeds = range(first, first + args.count)
    targets = [c for seed in seeds for c in companions(out / f"{args.type}_{seed}{ext}")]
    inputs = _model_file(args)
    check_new_outputs(targets, "--out-dir", overwrite=args.overwrite, inputs=inputs)
    written = 0
    for seed in tqdm(seeds, desc=f"{args.type} buildings", unit="building"):
        written += len(save(generate_from(gen, seed), out / f"{args.type}_{seed}{ext}", **options))
    print(f"wrote {args.count} buildings ({written} files) to {out}")
    return 0
