"""The learned-explorer study across training seeds: realistic-trained against random-trained, and both against the classical explorers.

Every model ``learned_<kind>_seed<N>`` (kind ``realistic``: trained on generated offices,
schools and houses; ``random``: on World-Generator-like random maps, the same budget) runs on
the sets of ``experiments/learned_explorer.py``: generated offices, schools and houses (10 seeds
from 1000, default sizes and step limits: never trained or tuned on) and every shared real plan
(one episode each; the sets, their labels and plans are that script's, imported as a sibling
module). The classical explorers' episodes on those sets are read from that script's run
(``--baselines``): they do not depend on the model.

The report gives, per model and per kind (each building's AUC averaged over the kind's seeds),
the learned explorer's paired difference from the nearest-frontier, utility and structure
explorers, and realistic-trained minus random-trained, paired by building, with 95% bootstrap
intervals; then the learned-explorer issue's targets, met or not.

Full run (about 6 minutes per model not yet evaluated, on 2 cores)::

    .venv/bin/python experiments/learned_seeds.py --out experiments/results

writes ``learned_seeds.md`` and each model's results in ``learned_seeds/<model>/``; a model
whose results are there already is not run again. ``--small`` runs the pipeline on houses in
seconds, with whatever models are found (the tests do).

``--track ppo-global-map`` asks the same of the second track, primitive-action PPO with the
robot's whole map (``realistic-indoor train --preset global-map``): models
``ppo_global_<kind>_seed<N>`` in ``experiments/results/ppo_global_models/``, run as ``ppo:MODEL``,
reported in ``ppo_global_seeds.md`` and ``ppo_global_seeds/<model>/``. ``--track
learned-structure-utility`` asks it of the learned explorer cloned from the ``structure-utility``
rule (``realistic-indoor train --preset learned-one-rule --teacher structure-utility``): models
``learned_su_<kind>_seed<N>`` in ``experiments/results/learned_su_models/``, reported in
``learned_su_seeds.md``; ``--track learned-structure-utility-area``, of the one cloned from the
``structure-utility-area`` rule: models ``learned_sua_<kind>_seed<N>`` in
``experiments/results/learned_sua_models/``, reported in ``learned_sua_seeds.md``; ``--track
learned-structure-utility-area-short``, of the recipe's rule (``structure-utility-area-short``)
cloned in every id (``--preset learned-one-rule``): models ``learned_suas_<kind>_seed<N>`` in
``experiments/results/learned_suas_models/``, reported in ``learned_suas_seeds.md``; ``--track
learned-house-rule``, of that rule with the ``gain`` rule in houses and a scorer that sees
three figures of the decision (``--preset learned-house-rule``): models
``learned_hr_<kind>_seed<N>`` in ``experiments/results/learned_hr_models/``, reported in
``learned_hr_seeds.md``; ``--track learned-pooled``, of the recipe as it is now (those rules, a
scorer that also sees a learned summary of the decision's candidates, every id weighed alike
in cloning: ``--preset learned``), whose realistic seed-0 model is the package's: models
``learned_pool_<kind>_seed<N>`` in ``experiments/results/learned_pool_models/``, reported in
``learned_pool_seeds.md``.
"""

from __future__ import annotations

import argparse
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path
from statistics import fmean
from typing import Any

from learned_explorer import GENERATED, REAL, Setup, env_sets

ROOT = Path(__file__).resolve().parents[1]
BASELINES = ROOT / "experiments" / "results" / "learned_explorer" / "results.json"
CLASSICAL = ("frontier", "utility", "structure")
KINDS = ("realistic", "random")
METRIC = "coverage_auc"


@dataclass(frozen=True)
class Track:
    """A kind of trained explorer the study compares across seeds and training maps.

    Attributes:
        prefix: Model names are ``<prefix>_<kind>_seed<N>``.
        agent: The agent name a model runs as: ``<agent>:<model.zip>``.
        models: The folder of the models.
        report: Name of the report (``<report>.md``) and of the folder of results per model.
        title: The report's title.
        label: What the report calls the explorer in the targets' lines.
        preset: The ``realistic-indoor train`` options that train its models (``--preset`` and more).
        committed: Models kept elsewhere than ``models``, by name.
        teacher: The rule a learned model must have cloned (its ``.json``'s ``config.teacher``;
            ``structure`` where the ``.json`` predates the option); ``None``: not checked.
        recipe: The learned preset its models were trained with: their ``.json``'s rules per id
            and scorer (:data:`RECIPE_KEYS`) must be that preset's (with ``teacher``); a key the
            ``.json`` predates counts as the recipe before it. Checked with ``teacher``.
    """

    prefix: str
    agent: str
    models: Path
    report: str
    title: str
    label: str
    preset: str
    committed: dict[str, Path] = field(default_factory=dict)
    teacher: str | None = None
    recipe: str = "learned-one-rule"

    @property
    def name_pattern(self) -> re.Pattern:
        """``<prefix>_<kind>_seed<N>``, kind and seed as groups."""
        return re.compile(rf"^{re.escape(self.prefix)}_(realistic|random)_seed(\d+)$")


TRACKS = {
    "learned": Track(
        "learned",
        "learned",
        ROOT / "experiments" / "results" / "learned_explorer_models",
        "learned_seeds",
        "The learned explorer across training seeds: realistic-trained and random-trained",
        "learned",
        "learned-one-rule --teacher structure",
        teacher="structure",
    ),
    "ppo-global-map": Track(
        "ppo_global",
        "ppo",
        ROOT / "experiments" / "results" / "ppo_global_models",
        "ppo_global_seeds",
        "Primitive-action PPO with the global map: realistic-trained and random-trained",
        "PPO (global map)",
        "global-map",
    ),
    "learned-structure-utility": Track(
        "learned_su",
        "learned",
        ROOT / "experiments" / "results" / "learned_su_models",
        "learned_su_seeds",
        "The learned explorer cloned from the structure-utility rule: realistic-trained and random-trained",
        "learned (structure-utility)",
        "learned-one-rule --teacher structure-utility",
        teacher="structure-utility",
    ),
    "learned-structure-utility-area": Track(
        "learned_sua",
        "learned",
        ROOT / "experiments" / "results" / "learned_sua_models",
        "learned_sua_seeds",
        "The learned explorer cloned from the structure-utility-area rule: realistic-trained and random-trained",
        "learned (structure-utility-area)",
        "learned-one-rule --teacher structure-utility-area",
        teacher="structure-utility-area",
    ),
    "learned-structure-utility-area-short": Track(
        "learned_suas",
        "learned",
        ROOT / "experiments" / "results" / "learned_suas_models",
        "learned_suas_seeds",
        "The learned explorer cloned from the structure-utility-area-short rule: realistic-trained and random-trained",
        "learned (structure-utility-area-short)",
        "learned-one-rule --teacher structure-utility-area-short",
        teacher="structure-utility-area-short",
    ),
    "learned-house-rule": Track(
        "learned_hr",
        "learned",
        ROOT / "experiments" / "results" / "learned_hr_models",
        "learned_hr_seeds",
        "The learned explorer cloned from the structure-utility-area-short rule, the gain rule in houses",
        "learned (house rule)",
        "learned-house-rule",
        teacher="structure-utility-area-short",
        recipe="learned-house-rule",
    ),
    "learned-pooled": Track(
        "learned_pool",
        "learned",
        ROOT / "experiments" / "results" / "learned_pool_models",
        "learned_pool_seeds",
        "The learned explorer with the pooled scorer and balanced cloning (the recipe)",
        "learned (pooled)",
        "learned",
        # the realistic seed-0 model is the package's own (the recipe)
        {"learned_pool_realistic_seed0": ROOT / "realistic_indoor" / "data" / "learned_explorer.zip"},
        "structure-utility-area-short",
        recipe="learned",
    ),
}
"""The study's tracks: the learned explorer, primitive-action PPO given the global map, the
learned explorer cloned from the ``structure-utility``, ``structure-utility-area`` and
``structure-utility-area-short`` rules (``--teacher``) instead of ``structure``, the recipe
that clones the ``gain`` rule in houses with a scorer that sees the decision's context, and the
recipe as it is, whose scorer also sees a learned summary of the candidates and whose cloning
weighs every id alike."""
NAME = TRACKS["learned"].name_pattern

TARGETS = (
    ("offices", "frontier", 0.01, True),
    ("offices", "structure", -0.005, False),
    ("schools", "frontier", 0.01, True),
    ("schools", "structure", -0.005, False),
    ("houses", "frontier", -0.01, False),
    ("real offices", "frontier", 0.0, False),
    ("real schools", "frontier", 0.0, False),
)
"""The issue's targets: (set, classical explorer, least mean difference, interval must exclude 0)."""


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--small", action="store_true", help="houses, short episodes: seconds, for tests")
    p.add_argument(
        "--out",
        default=None,
        help="output folder (default runs/learned_seeds; with --small a new temporary one); "
        "--out experiments/results regenerates the committed results",
    )
    p.add_argument(
        "--track", choices=sorted(TRACKS), default="learned", help="which explorer (default learned)"
    )
    p.add_argument(
        "--models", default=None, help="folder of <prefix>_<kind>_seed<N>.zip models (default: the track's)"
    )
    p.add_argument(
        "--baselines",
        default=str(BASELINES),
        help="results.json of experiments/learned_explorer.py with the classical explorers' episodes",
    )
    p.add_argument("--workers", type=int, default=None, help="processes (default: one per core)")
    p.add_argument("--report-only", action="store_true", help="redo the report from the saved results")
    return p.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    from realistic_indoor.cli import checkout_commit, run_folder, script_command, write_report
    from realistic_indoor.errors import ConfigError
    from realistic_indoor.evaluation import make_tasks, read_results, run_tasks, write_results

    args = parse_args(argv)
    track = TRACKS[args.track]
    runs = ROOT / "runs" / track.report
    out = run_folder(args.out, runs, small=args.small, report_only=args.report_only, name=track.report)
    baselines, base_meta = ([], {}) if args.small else read_results(args.baselines)
    folder = Path(args.models) if args.models else track.models
    models = find_models(folder, track)
    if not models:
        raise ConfigError(
            f"no {track.prefix}_<kind>_seed<N>.zip models in {folder}; "
            f"train them with realistic-indoor train --preset {track.preset}"
        )
    episodes, sets, env_kwargs = (
        (2, ("houses",), {"max_steps": 60}) if args.small else (10, tuple(GENERATED), {})
    )
    generated, real = env_sets(Setup(episodes, sets=sets, real=not args.small, env_kwargs=env_kwargs))
    results = [r for r in baselines if r.agent in CLASSICAL]
    if args.small:
        tasks = make_tasks(list(CLASSICAL), generated, episodes, seed=1000)
        results += run_tasks(tasks, workers=args.workers or 1)
    commit = checkout_commit(ROOT)
    for name, path in models.items():
        folder = out / track.report / name
        if (folder / "results.json").is_file():
            mine, _ = read_results(folder / "results.json")
        else:
            if args.report_only:
                continue
            print(f"evaluating {name} ({path})", flush=True)
            agent = f"{track.agent}:{path}"
            tasks = make_tasks([agent], generated, episodes, seed=1000)
            if real:
                tasks += make_tasks([agent], real, 1, seed=1000)
            mine = run_tasks(tasks, workers=args.workers or (1 if args.small else None))
            for r in mine:
                r.agent = name
            model_meta = {"model": _relative(path), "commit": commit, "episodes": episodes, "seed": 1000}
            write_results(mine, folder, model_meta)
        results += [r for r in mine if r.agent == name]
    meta = {
        "command": script_command("experiments/learned_seeds.py", argv),
        "commit": commit,
        "baselines": f"{_relative(Path(args.baselines))} (commit {base_meta.get('commit', '-')})"
        if not args.small
        else "run here",
        "episodes": episodes,
        "seed": 1000,
        "sets": [*sets, *(REAL if real else ())],
        "track": args.track,
    }
    return write_report(out, track.report, analyse, results, meta)


def find_models(folder: Path, track: Track = TRACKS["learned"]) -> dict[str, Path]:
    """The models of the study, by name (``<prefix>_<kind>_seed<N>``), realistic first, then by seed."""
    pattern = track.name_pattern
    found = {p.stem: p for p in folder.glob(f"{track.prefix}_*_seed*.zip") if pattern.match(p.stem)}
    for name, path in track.committed.items():
        if name not in found and (folder / f"{name}.json").is_file() and path.is_file():
            found[name] = path
    for name in found:
        _check_recipe(folder / f"{name}.json", track)
    return dict(sorted(found.items(), key=lambda item: _kind_seed(item[0], pattern)))


RECIPE_KEYS = {
    "teacher": "structure",
    "teacher_by_id": [],
    "scorer_context": False,
    "scorer_pool": 0,
    "bc_balance": False,
}
"""The training options that tell the learned explorer's recipes apart, with the value a model's
``.json`` from before each option means."""


def _check_recipe(meta: Path, track: Track) -> None:
    """Refuse a model whose ``.json`` says it was trained with other rules or another scorer than the track's."""
    import json

    from realistic_indoor.agents.rl.learned import learned_preset
    from realistic_indoor.errors import ConfigError

    if track.teacher is None or not meta.is_file():
        return
    config = json.loads(meta.read_text()).get("config", {})
    mine = {key: config.get(key, before) for key, before in RECIPE_KEYS.items()}
    wanted = learned_preset(track.recipe, teacher=track.teacher).to_dict()
    differ = [key for key in RECIPE_KEYS if mine[key] != wanted[key]]
    if differ:
        said = ", ".join(f"{key} {mine[key]!r}" for key in differ)
        theirs = ", ".join(f"{key} {wanted[key]!r}" for key in differ)
        raise ConfigError(
            f"{meta.name}: the model was trained with {said}, which the {track.prefix} models are not "
            f"({theirs}); move it out of the folder or train it with --preset {track.preset}"
        )


def _kind_seed(name: str, pattern: re.Pattern = NAME) -> tuple[int, int]:
    kind, seed = pattern.match(name).groups()
    return KINDS.index(kind), int(seed)


def _relative(path: Path) -> str:
    try:
        return str(path.resolve().relative_to(ROOT))
    except ValueError:
        return path.name


def analyse(results: list, meta: dict[str, Any]) -> str:
    """The report: per model and per kind, differences from the classical explorers; realistic minus random."""
    track = TRACKS[meta.get("track", "learned")]
    pattern = track.name_pattern
    values: dict[tuple[str, str], dict[tuple[str, int], float]] = {}
    for r in results:
        values.setdefault((r.group, r.agent), {})[(r.env, r.seed)] = float(getattr(r, METRIC))
    sets = [s for s in meta["sets"] if any(g == s for g, _ in values)]
    models = sorted({a for _, a in values if pattern.match(a)}, key=lambda m: _kind_seed(m, pattern))
    kinds = {k: [m for m in models if pattern.match(m).group(1) == k] for k in KINDS}
    for kind, members in kinds.items():
        for s in sets:
            per = [values.get((s, m), {}) for m in members]
            keys = sorted(set.intersection(*(set(p) for p in per))) if per and all(per) else []
            if keys:
                values[(s, kind)] = {k: fmean(p[k] for p in per) for k in keys}
    lines = [
        f"# {track.title}",
        "",
        f"Regenerate with `{meta['command']}` (commit {meta['commit']}; classical explorers' episodes: "
        f"{meta['baselines']}).",
        "",
        f"Coverage AUC. Generated sets: {meta['episodes']} seeds each from {meta['seed']}, default sizes "
        "and step limits; real sets: every shared plan, one episode. A difference is paired by building "
        "and start: mean and 95% bootstrap interval (* the interval excludes 0). A kind's row averages "
        "each building's AUC over the kind's models first.",
        "",
        f"Models: {', '.join(models) or 'none'}.",
        "",
        "## Against the classical explorers",
        "",
    ]
    head = ["set", "model", "episodes", "AUC", *(f"minus {b}" for b in CLASSICAL)]
    lines += ["| " + " | ".join(head) + " |", "|---" * len(head) + "|"]
    rows = [*models, *(k for k in KINDS if kinds[k])]
    for s in sets:
        for m in rows:
            mine = values.get((s, m))
            if not mine:
                continue
            label = m
            if m in KINDS:
                n = len(kinds[m])
                label = f"**{m} ({n} seed{'s' if n != 1 else ''})**"
            cells = [s, label, str(len(mine)), f"{fmean(mine.values()):.3f}"]
            cells += [_paired(mine, values.get((s, b), {})) for b in CLASSICAL]
            lines.append("| " + " | ".join(cells) + " |")
    lines += ["", "## Realistic-trained minus random-trained", ""]
    lines += ["| set | buildings | realistic | random | difference |", "|---|---|---|---|---|"]
    for s in sets:
        a, b = values.get((s, "realistic"), {}), values.get((s, "random"), {})
        keys = [k for k in a if k in b]
        if keys:
            row = [s, str(len(keys)), f"{fmean(a[k] for k in keys):.3f}", f"{fmean(b[k] for k in keys):.3f}"]
            lines.append("| " + " | ".join([*row, _paired(a, b)]) + " |")
    lines += ["", "## The learned-explorer issue's targets (realistic-trained, averaged over its seeds)", ""]
    for s, other, least, apart in TARGETS:
        mine, theirs = values.get((s, "realistic"), {}), values.get((s, other), {})
        keys = [k for k in mine if k in theirs]
        if not keys:
            continue
        d = _difference([mine[k] - theirs[k] for k in keys])
        met = d.mean >= least and (not apart or d.low > 0)
        want = f">= {least:+.3f}" + (" with the interval above 0" if apart else "")
        lines.append(
            f"- {s}: {track.label} minus {other} {d.mean:+.3f} [{d.low:+.3f}, {d.high:+.3f}], asked {want}: "
            f"{'met' if met else 'not met'}"
        )
    return "\n".join(lines) + "\n"


def _difference(diffs: list[float]) -> Any:
    from realistic_indoor.evaluation.aggregate import bootstrap_mean

    return bootstrap_mean(diffs)


def _paired(mine: dict, other: dict) -> str:
    keys = [k for k in mine if k in other]
    if not keys:
        return "-"
    d = _difference([mine[k] - other[k] for k in keys])
    apart = d.n > 1 and (d.low > 0 or d.high < 0)
    return f"{d.mean:+.3f} [{d.low:+.3f}, {d.high:+.3f}]{' *' if apart else ''}"


if __name__ == "__main__":
    from realistic_indoor.cli import run_script

    sys.exit(run_script(main, "learned_seeds.py"))
