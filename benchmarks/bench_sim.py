"""Benchmark of the simulator (realistic_indoor.sim) on one core: prints Markdown tables.

Measures, for buildings of several sizes: raster and world build time, raycasting rate (rays/s
after JIT warm-up), one scan with the default laser, a physics control step, a map update, a
local-map extraction and memory per world; then a physics safety run over many random steps
(robot never in a wall nor out of the building, checked against the plan's geometry); then the
first-call latency of the numba kernels with and without the on-disk cache.

Buildings are real plans from ``../shared/data/real_floorplans`` (chosen to span sizes) or,
with ``--source generator``, offices from ``realistic_indoor.generator``.

Usage::

    .venv/bin/python benchmarks/bench_sim.py            # full run, a few minutes
    .venv/bin/python benchmarks/bench_sim.py --quick    # smaller counts, ~1 minute
"""

from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
PLANS = ROOT.parent / "shared" / "data" / "real_floorplans"
PLAN_FILES = (
    "school/Borchen4_updated.xml",
    "office/Milano-1.xml",
    "office/AtlanticSuites.xml",
    "school/Neulengbach1_updated.xml",
    "school/virginia_cross_updated.xml",
)
GENERATED_AREAS_M2 = (300, 1000, 2000, 4000, 8000)


def main(argv: list[str] | None = None) -> None:
    """Run the benchmark and print its tables."""
    args = _parse(argv)
    buildings = _buildings(args)
    print(f"# Simulator benchmark ({'quick' if args.quick else 'full'}; one process, one core)\n")
    _per_building_table(buildings, args)
    _safety_table(buildings, args.safety_steps)
    if not args.skip_latency:
        _latency_table()


def _parse(argv: list[str] | None) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument(
        "--source", choices=("plans", "generator"), default="plans", help="where buildings come from"
    )
    p.add_argument("--plans-dir", type=Path, default=PLANS, help="folder of the real floor plans")
    p.add_argument("--quick", action="store_true", help="fewer repetitions (about a minute)")
    p.add_argument("--safety-steps", type=int, default=None, help="random physics steps in the safety run")
    p.add_argument("--skip-latency", action="store_true", help="skip the first-call latency subprocesses")
    p.add_argument("--seed", type=int, default=0)
    args = p.parse_args(argv)
    if args.safety_steps is None:
        args.safety_steps = 20_000 if args.quick else 100_000
    args.reps = 300 if args.quick else 2000
    return args


def _buildings(args: argparse.Namespace) -> list[tuple[str, object]]:
    if args.source == "generator":
        from realistic_indoor.generator import generate

        return [
            (f"generated office {a} m2", generate("office", area_m2=a, seed=args.seed))
            for a in GENERATED_AREAS_M2
        ]
    from realistic_indoor.io import load

    if not args.plans_dir.is_dir():
        sys.exit(f"real plans not found at {args.plans_dir}; pass --plans-dir or --source generator")
    return [(Path(f).stem.removesuffix("_updated"), load(args.plans_dir / f)) for f in PLAN_FILES]


def _per_building_table(buildings: list[tuple[str, object]], args: argparse.Namespace) -> None:
    rows = []
    for name, building in buildings:
        rows.append(_measure(name, building, args))
    print("## Per building\n")
    header = (
        "| building | area m2 | raster cells | raster ms | world ms | rays/s (M) | scan us | "
        "physics us | map update us | local map us (64/84 px) | step total us | MB per world |"
    )
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    for r in rows:
        print(
            f"| {r['name']} | {r['area']:.0f} | {r['cells'] / 1e6:.2f} M | {r['raster_ms']:.1f} | "
            f"{r['world_ms']:.1f} | {r['rays_m']:.1f} | {r['scan_us']:.1f} | {r['physics_us']:.1f} | "
            f"{r['map_us']:.1f} | {r['local64_us']:.1f} / {r['local84_us']:.1f} | {r['total_us']:.1f} | "
            f"{r['mb']:.1f} |"
        )
    print(
        "\nrays/s: 1,080-beam full-circle fans from random free poses, 10 m range. scan: default "
        "laser (109 beams over 270 degrees, noise). physics: one 0.2 s control step (4 sub-steps). "
        "map update: one default scan into the robot's map. step total: physics + scan + map update "
        "+ 64 px local map along a random drive.\n"
    )


def _median_us(fn, reps: int) -> float:
    """Median time of ``fn()`` over ``reps`` calls, in microseconds (after one warm-up call)."""
    fn()
    times = np.empty(reps)
    for i in range(reps):
        t = time.perf_counter()
        fn()
        times[i] = time.perf_counter() - t
    return float(np.median(times) * 1e6)


def _measure(name: str, building, args: argparse.Namespace) -> dict:
    from realistic_indoor.sim import (
        Lidar,
        LidarConfig,
        LocalMapConfig,
        RayHits,
        Robot,
        RobotMap,
        World,
        rasterize,
    )

    building.walls  # noqa: B018 - the building's own cached geometry, not the simulator's cost
    raster_ms = _median_us(lambda: rasterize(building), 5) / 1e3
    world_ms = _median_us(lambda: World(building), 3) / 1e3
    world = World(building)
    rng = np.random.default_rng(args.seed)
    poses = _free_poses(world, rng, 200)

    fan = np.linspace(-math.pi, math.pi, 1080, endpoint=False)
    cos_f, sin_f = np.cos(fan), np.sin(fan)
    out = RayHits(np.empty(1080, np.float32), np.empty(1080, np.uint8))
    world.raycaster.cast_into(0.0, 0.0, 0.0, cos_f, sin_f, 10.0, out)
    n_fans = 200 if args.quick else 1000
    t = time.perf_counter()
    for i in range(n_fans):
        x, y, th = poses[i % len(poses)]
        world.raycaster.cast_into(x, y, th, cos_f, sin_f, 10.0, out)
    rays_m = n_fans * 1080 / (time.perf_counter() - t) / 1e6

    lidar = Lidar(LidarConfig())
    scan_us = _median_us(lambda: lidar.scan(world.raycaster, tuple(poses[0]), rng), args.reps)
    robot = Robot.in_world(world)
    robot_map = RobotMap(world)
    physics_us = _median_us(lambda: robot.step(rng.uniform(-0.3, 1.0), rng.uniform(-2, 2)), args.reps)
    robot.reset(world.start_pose)
    local64 = RobotMap(world, LocalMapConfig(64, 0.2))
    local84 = RobotMap(world, LocalMapConfig(84, 0.2))
    local64_us = _median_us(lambda: local64.local_view(world.start_pose), args.reps)
    local84_us = _median_us(lambda: local84.local_view(world.start_pose), args.reps)

    map_times, total_times = [], []
    robot_map.update(lidar.scan(world.raycaster, robot.pose, rng))
    for i in range(args.reps):
        if i % 5 == 0:
            v, w = rng.uniform(0.2, 1.0), rng.uniform(-1.5, 1.5)
        t0 = time.perf_counter()
        robot.step(v, w)
        scan = lidar.scan(world.raycaster, robot.pose, rng)
        t1 = time.perf_counter()
        robot_map.update(scan)
        t2 = time.perf_counter()
        robot_map.local_view(robot.pose)
        t3 = time.perf_counter()
        map_times.append(t2 - t1)
        total_times.append(t3 - t0)
    return {
        "name": name,
        "area": building.area,
        "cells": world.raster.grid.size,
        "raster_ms": raster_ms,
        "world_ms": world_ms,
        "rays_m": rays_m,
        "scan_us": scan_us,
        "physics_us": physics_us,
        "map_us": float(np.median(map_times) * 1e6),
        "local64_us": local64_us,
        "local84_us": local84_us,
        "total_us": float(np.median(total_times) * 1e6),
        "mb": (world.nbytes + robot_map.nbytes) / 1e6,
    }


def _free_poses(world, rng: np.random.Generator, n: int) -> np.ndarray:
    cells = np.argwhere(world.clearance_m >= 0.3)
    xy = world.raster.cell_to_world(*cells[rng.integers(len(cells), size=n)].T)
    return np.column_stack([xy, rng.uniform(-math.pi, math.pi, n)])


def _safety_table(buildings: list[tuple[str, object]], total_steps: int) -> None:
    import shapely

    from realistic_indoor.building.walls import door_gap
    from realistic_indoor.sim import Robot, RobotConfig, World

    rng = np.random.default_rng(1)
    config = RobotConfig()
    per = total_steps // len(buildings)
    print(f"## Physics safety: {per * len(buildings):,} random control steps\n")
    print(
        "| building | steps | min distance centre-wall (m) | outside the building | wall contacts | us/step |"
    )
    print("|---|---|---|---|---|---|")
    for name, building in buildings:
        world = World(building)
        robot = Robot.in_world(world, config)
        poses = np.empty((per, 2))
        contacts = 0
        start_cells = np.argwhere(world.clearance_m >= config.radius_m + 0.05)
        t = time.perf_counter()
        for i in range(per):
            if i % 500 == 0:
                xy = world.raster.cell_to_world(*start_cells[rng.integers(len(start_cells))])
                robot.reset((*xy, rng.uniform(-math.pi, math.pi)))
            if i % 4 == 0:
                v, w = rng.uniform(-0.3, 1.0), rng.uniform(-2.0, 2.0)
            contacts += robot.step(v, w).collided
            poses[i] = robot.pose[:2]
        us = (time.perf_counter() - t) / per * 1e6
        walls = shapely.MultiLineString([list(map(tuple, s)) for s in building.walls])
        floor = shapely.union_all([r.polygon for r in building.rooms] + [door_gap(d) for d in building.doors])
        points = shapely.points(poses)
        d_min = float(shapely.distance(points, walls).min())
        outside = int((~shapely.contains(floor.buffer(1e-6), points)).sum())
        print(f"| {name} | {per:,} | {d_min:.3f} | {outside} | {contacts:,} | {us:.1f} |")
    print(
        f"\nRobot radius {config.radius_m} m, walls 0.1 m thick: touching a wall puts the centre "
        f"{config.radius_m + 0.05:.2f} m from its centre line.\n"
    )


_LATENCY_CODE = """
import time
t0 = time.perf_counter()
import numpy as np
from realistic_indoor.building import Building, Door, Room
from realistic_indoor.sim import Lidar, RobotMap, Robot, World
t1 = time.perf_counter()
rooms = (Room.rectangle("c", "corridor", "corridor", (0, 0, 10, 2)),
         Room.rectangle("a", "medium", "office", (0, 2, 10, 6)))
b = Building("office", rooms, (Door("d", "a", "c", 5.0, 2.0), Door("e", "c", None, 0.0, 1.0, 1.2, 1.5708)))
world = World(b)
robot = Robot.in_world(world)
m = RobotMap(world)
m.update(Lidar().scan(world.raycaster, robot.pose, np.random.default_rng(0)))
m.local_view(robot.pose)
world.raycaster.visible((1.0, 1.0), np.array([[2.0, 1.0]]))
t2 = time.perf_counter()
print(f"{t1 - t0:.3f} {t2 - t1:.3f}")
"""


def _latency_table() -> None:
    print("## First-call latency in a fresh process (s)\n")
    print("| numba cache | imports | first world + scan + map + local view |")
    print("|---|---|---|")
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        for label in ("empty (compiles every kernel)", "warm (loads from cache)"):
            out = subprocess.run(
                [sys.executable, "-c", _LATENCY_CODE],
                env=env,
                capture_output=True,
                text=True,
                check=True,
                cwd=ROOT,
            ).stdout.split()
            print(f"| {label} | {float(out[0]):.2f} | {float(out[1]):.2f} |")
    print()


if __name__ == "__main__":
    main()
