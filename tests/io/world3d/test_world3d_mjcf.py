"""MuJoCo models: MuJoCo compiles them, and its rays see the walls the project's own laser sees.

Needs the ``sim3d`` extra (``pip install -e ".[sim3d]"``); skipped with that reason without it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import realistic_indoor as ri
from realistic_indoor.io import save
from realistic_indoor.io.world3d import WorldOptions, building_boxes
from realistic_indoor.sim import World, WorldConfig
from realistic_indoor.sim.lidar import Lidar, LidarConfig
from realistic_indoor.sim.raster import RASTER_WALL

mujoco = pytest.importorskip("mujoco", reason="MuJoCo is in the sim3d extra: pip install -e '.[sim3d]'")

RAY_HEIGHT_M = 0.3
MAX_RANGE_M = 10.0
TOLERANCE_M = 0.05


def _compile(building, path, **options):
    save(building, path, **options)
    model = mujoco.MjModel.from_xml_path(str(path))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return model, data


def _points_in_rooms(building, world: World, count: int = 12) -> list[tuple[float, float]]:
    """``count`` points spread over the rooms (a 0.5 m lattice), each at least 0.3 m from any wall.

    The lattice is off the 5 cm grid the walls' box faces lie on, by different amounts in x and
    y (2.13 and 2.91 cm past it), so no level beam runs exactly along a face and no diagonal one
    through a box's corner, where both ray casters would be right to disagree.
    """
    from shapely import contains_xy

    x0, y0, x1, y1 = building.bounds
    xs, ys = np.meshgrid(np.arange(x0 + 0.2713, x1, 0.5), np.arange(y0 + 0.2791, y1, 0.5))
    xy = np.column_stack([xs.ravel(), ys.ravel()])
    inside = np.any([contains_xy(r.polygon, xy[:, 0], xy[:, 1]) for r in building.rooms], axis=0)
    xy = xy[inside & (world.clearance_at(xy) >= 0.3)]
    return [tuple(p) for p in xy[np.linspace(0, len(xy) - 1, count).round().astype(int)]]


def _mujoco_range(model, data, x: float, y: float, angle: float) -> float:
    """Distance to the first geom along a level ray (m), or ``inf`` if it meets none."""
    direction = np.array([math.cos(angle), math.sin(angle), 0.0])
    d = mujoco.mj_ray(
        model, data, np.array([x, y, RAY_HEIGHT_M]), direction, None, 1, -1, np.zeros(1, np.int32)
    )
    return d if d >= 0 else math.inf


def _compare(building, model, data, world: World) -> tuple[list[float], list[tuple]]:
    """Each laser beam's error against MuJoCo (rays that hit a wall), and the disagreements."""
    lidar = Lidar(LidarConfig(fov_rad=2 * math.pi, n_beams=360, max_range_m=MAX_RANGE_M, noise_std_m=0.0))
    errors, wrong = [], []
    for x, y in _points_in_rooms(building, world):
        scan = lidar.scan(world.raycaster, (x, y, 0.0))
        for angle, laser, kind in zip(lidar.offsets_rad, scan.true.range_m, scan.true.kind, strict=True):
            seen = _mujoco_range(model, data, x, y, angle)
            if kind == RASTER_WALL:
                errors.append(abs(seen - laser))
                if errors[-1] > TOLERANCE_M:
                    wrong.append((x, y, angle, float(laser), seen))
            elif seen < laser - TOLERANCE_M:  # out through an entrance, or nothing within range
                wrong.append((x, y, angle, float(laser), seen))
    return errors, wrong


def _ill_conditioned(model, data, ray: tuple, shift_m: float) -> bool:
    """Whether MuJoCo's range changes by more than the tolerance when the ray moves ``shift_m`` sideways.

    Such rays graze a wall or clip a corner: a raster of ``shift_m`` cells cannot resolve them.
    """
    x, y, angle, _laser, seen = ray
    nx, ny = -math.sin(angle) * shift_m, math.cos(angle) * shift_m
    moved = [_mujoco_range(model, data, x + s * nx, y + s * ny, angle) for s in (-1, 1)]
    return max(abs(m - seen) for m in moved) > TOLERANCE_M


def test_mujoco__compiles_walls_floor_and_start_site(office, tmp_path):
    model, _data = _compile(office, tmp_path / "office.mjcf.xml")
    boxes = building_boxes(office, WorldOptions())
    assert model.ngeom == 1 + len(boxes)
    names = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_GEOM, i) for i in range(model.ngeom)]
    assert names == ["floor", *(b.name for b in boxes)]
    assert model.geom_type[0] == mujoco.mjtGeom.mjGEOM_PLANE
    assert set(model.geom_type[1:].tolist()) == {int(mujoco.mjtGeom.mjGEOM_BOX)}
    wall = boxes[0]
    assert model.geom_size[1] == pytest.approx(np.array(wall.size) / 2)
    assert model.geom_pos[1] == pytest.approx(wall.centre)
    x, y, _yaw = World(office).start_pose
    site = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, "robot_start")
    assert model.site_pos[site] == pytest.approx([x, y, 0.0])


def test_mujoco__rays_agree_with_the_laser_within_5_cm(office, tmp_path):
    """Generated plans lie on the raster's 5 cm grid: every beam agrees at the default resolution."""
    model, data = _compile(office, tmp_path / "office.mjcf.xml")
    errors, wrong = _compare(office, model, data, World(office))
    assert len(errors) > 2000
    assert wrong == []
    assert max(errors) < TOLERANCE_M


@pytest.mark.parametrize("plan", ["slanted", "real"])
def test_mujoco__rays_agree_on_slanted_walls(plan, request, tmp_path):
    """Slanted walls at a 1 cm raster: beams agree within 5 cm but for grazing ones (under 1%)."""
    if plan == "real":
        from realistic_indoor.io import load

        b = load(request.getfixturevalue("real_plans_dir") / "office" / "Off-2.xml")
    else:
        b = request.getfixturevalue(plan)
    model, data = _compile(b, tmp_path / "plan.mjcf.xml")
    world = World(b, WorldConfig(resolution_m=0.01))
    errors, wrong = _compare(b, model, data, world)
    grazing = [ray for ray in wrong if _ill_conditioned(model, data, ray, 0.01)]
    assert [ray for ray in wrong if ray not in grazing] == []
    assert len(grazing) <= 0.01 * len(errors)
    assert np.median(errors) < 0.01


def test_mujoco__closed_entrances_stop_the_rays_that_left(slanted, tmp_path):
    model, data = _compile(slanted, tmp_path / "closed.mjcf.xml", exterior_doors_open=False)
    assert _mujoco_range(model, data, 2.0, 2.0, math.pi) == pytest.approx(2.0 - 0.05)
    model, data = _compile(slanted, tmp_path / "open.mjcf.xml")
    assert _mujoco_range(model, data, 2.0, 2.0, math.pi) == math.inf


@pytest.mark.parametrize("kind", ["office", "school", "house", "random"])
def test_mujoco__compiles_every_generated_type(kind, tmp_path):
    b = ri.generate(kind, seed=5)
    model, _data = _compile(b, tmp_path / f"{kind}.mjcf.xml", exterior_doors_open=False)
    assert model.ngeom == 1 + len(building_boxes(b, WorldOptions(exterior_doors_open=False)))


@pytest.mark.slow
def test_mujoco__compiles_every_shared_real_plan(real_plans_dir, tmp_path):
    from realistic_indoor.io import load

    for plan in sorted(real_plans_dir.glob("*/*.xml")):
        b = load(plan)
        model, _data = _compile(b, tmp_path / "real.mjcf.xml")
        assert model.ngeom == 1 + len(building_boxes(b, WorldOptions())), plan.name
