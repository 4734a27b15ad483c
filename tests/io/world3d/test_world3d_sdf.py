"""Gazebo worlds: their wall boxes are the plan's walls, as read back and as libsdformat reads them.

The SDFormat test builds a few lines of C++ around ``sdf::Root::Load`` (the reader Gazebo uses)
when a C++ compiler and libsdformat's development files are there (Debian: ``apt-get install
libsdformat-dev g++``, SDFormat 12), and skips with the reason otherwise.
"""

from __future__ import annotations

import math
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from realistic_indoor.io import save
from realistic_indoor.sim import World

LOADER = r"""
#include <iostream>
#include <sdf/sdf.hh>

// Load a world with libsdformat; print its errors, or its frames and every box collision.
int main(int argc, char **argv) {
  sdf::Root root;
  sdf::Errors errors = root.Load(argv[1]);
  for (const auto &e : errors) std::cout << "error " << e.Message() << "\n";
  if (!errors.empty() || root.WorldCount() != 1) return 1;
  const sdf::World *world = root.WorldByIndex(0);
  std::cout << "world " << world->Name() << "\n";
  for (uint64_t i = 0; i < world->FrameCount(); ++i) {
    auto p = world->FrameByIndex(i)->RawPose();
    std::cout << "frame " << world->FrameByIndex(i)->Name() << " " << p.Pos().X() << " " << p.Pos().Y()
              << " " << p.Pos().Z() << " " << p.Rot().Yaw() << "\n";
  }
  const sdf::Link *link = world->ModelByName("building")->LinkByName("walls");
  for (uint64_t i = 0; i < link->CollisionCount(); ++i) {
    const sdf::Collision *c = link->CollisionByIndex(i);
    auto p = c->RawPose();
    auto s = c->Geom()->BoxShape()->Size();
    std::cout.precision(12);
    std::cout << "box " << c->Name() << " " << p.Pos().X() << " " << p.Pos().Y() << " " << p.Pos().Z() << " "
              << p.Rot().Yaw() << " " << s.X() << " " << s.Y() << " " << s.Z() << "\n";
  }
  return 0;
}
"""


@pytest.fixture(scope="session")
def sdformat_loader(tmp_path_factory):
    """A program that loads a world with libsdformat (built once), or a skip saying what is missing."""
    compiler = shutil.which("g++") or shutil.which("c++")
    pkg_config = shutil.which("pkg-config")
    if compiler is None or pkg_config is None:
        pytest.skip(
            "no C++ compiler or pkg-config to build the libsdformat loader (apt-get install g++ pkg-config)"
        )
    listed = subprocess.run([pkg_config, "--list-package-names"], capture_output=True, text=True).stdout
    packages = sorted(
        (p for p in listed.split() if re.fullmatch(r"sdformat\d+", p)), key=lambda p: int(p[8:])
    )
    if not packages:
        pytest.skip("libsdformat development files not found (apt-get install libsdformat-dev)")
    flags = subprocess.run(
        [pkg_config, "--cflags", "--libs", packages[-1]], capture_output=True, text=True
    ).stdout
    folder = tmp_path_factory.mktemp("sdformat")
    (folder / "load.cc").write_text(LOADER, encoding="utf-8")
    exe = folder / "load"
    build = subprocess.run(
        [compiler, str(folder / "load.cc"), "-o", str(exe), *flags.split()], capture_output=True, text=True
    )
    assert build.returncode == 0, f"building the {packages[-1]} loader failed:\n{build.stderr}"
    return exe, packages[-1]


def _read_with_sdformat(loader, path):
    exe, _package = loader
    run = subprocess.run([str(exe), str(path)], capture_output=True, text=True)
    assert run.returncode == 0, f"libsdformat refused {path.name}:\n{run.stdout}{run.stderr}"
    lines = [line.split() for line in run.stdout.splitlines()]
    boxes = {w[1]: [float(v) for v in w[2:]] for w in lines if w[0] == "box"}
    frames = {w[1]: [float(v) for v in w[2:]] for w in lines if w[0] == "frame"}
    return boxes, frames


def _walls_from_boxes(boxes: dict, box_segments, thickness: float):
    """The wall boxes (``wall_<i>_collision``) in index order, as plan segments."""
    names = sorted((n for n in boxes if n.startswith("wall_")), key=lambda n: int(n.split("_")[1]))
    rows = np.array([boxes[n] for n in names])
    return box_segments(rows[:, :3], rows[:, 4], rows[:, 3], thickness), rows


def _boxes_from_xml(path):
    """``{collision name: [x, y, z, yaw, sx, sy, sz]}`` of the ``building`` model, read as XML."""
    root = ET.parse(path).getroot()
    model = root.find("world/model[@name='building']")
    out = {}
    for c in model.iter("collision"):
        x, y, z, _r, _p, yaw = (float(v) for v in c.findtext("pose").split())
        size = [float(v) for v in c.findtext("geometry/box/size").split()]
        out[c.get("name").removesuffix("_collision")] = [x, y, z, yaw, *size]
    return out


@pytest.mark.parametrize("plan", ["office", "slanted", "tiny_office"])
def test_sdf__wall_boxes_are_the_plans_walls_within_1_cm(plan, request, tmp_path, box_segments):
    b = request.getfixturevalue(plan)
    save(b, tmp_path / "w.sdf")
    found, rows = _walls_from_boxes(_boxes_from_xml(tmp_path / "w.sdf"), box_segments, 0.1)
    assert found.shape == b.walls.shape
    assert np.abs(found - b.walls).max() < 0.01
    assert np.allclose(rows[:, 2], 1.25) and np.allclose(rows[:, 5:], [0.1, 2.5])


def test_sdf__options_change_heights_and_thickness(slanted, tmp_path, box_segments):
    save(slanted, tmp_path / "w.world", wall_height_m=3.0, wall_thickness_m=0.2, door_height_m=2.2)
    boxes = _boxes_from_xml(tmp_path / "w.world")
    found, rows = _walls_from_boxes(boxes, box_segments, 0.2)
    assert np.abs(found - slanted.walls).max() < 0.01
    assert np.allclose(rows[:, 5:], [0.2, 3.0])
    assert boxes["lintel_d1"][2] == pytest.approx(2.6) and boxes["lintel_d1"][6] == pytest.approx(0.8)


@pytest.mark.parametrize("plan", ["office", "slanted"])
def test_sdformat__loads_without_errors_and_reads_the_plans_walls(
    plan, request, sdformat_loader, tmp_path, box_segments
):
    b = request.getfixturevalue(plan)
    for ending in ("sdf", "world"):
        save(b, tmp_path / f"w.{ending}", exterior_doors_open=False)
        boxes, frames = _read_with_sdformat(sdformat_loader, tmp_path / f"w.{ending}")
        found, _rows = _walls_from_boxes(boxes, box_segments, 0.1)
        assert np.abs(found - b.walls).max() < 0.01
        assert {n.rsplit("_", 1)[0] for n in boxes if n.startswith("door_")} == {
            f"door_{d.id}" for d in b.entrances
        }
        x, y, yaw = World(b).start_pose
        assert frames["robot_start"][:3] == pytest.approx([x, y, 0.0], abs=1e-5)
        assert math.remainder(frames["robot_start"][3] - yaw, 2 * math.pi) == pytest.approx(0.0, abs=1e-5)


@pytest.mark.parametrize("name", ["office/Off-2.xml", "school/stjoseph'scatholichighschool_updated.xml"])
def test_sdformat__loads_real_plans(name, real_plans_dir, sdformat_loader, tmp_path, box_segments):
    """Off-2 has thick walls (doors between two outlines), St Joseph's the most wall segments (534)."""
    from realistic_indoor.io import load

    b = load(real_plans_dir / name)
    save(b, tmp_path / "real.sdf")
    boxes, frames = _read_with_sdformat(sdformat_loader, tmp_path / "real.sdf")
    found, _rows = _walls_from_boxes(boxes, box_segments, 0.1)
    assert np.abs(found - b.walls).max() < 0.01
    assert "robot_start" in frames


@pytest.mark.slow
def test_sdf__every_shared_real_plan_gives_its_walls(real_plans_dir, tmp_path, box_segments):
    from realistic_indoor.io import load

    plans = sorted(real_plans_dir.glob("*/*.xml"))
    assert len(plans) == 55
    for plan in plans:
        b = load(plan)
        save(b, tmp_path / "real.sdf", door_height_m=2.5)
        found, _rows = _walls_from_boxes(_boxes_from_xml(tmp_path / "real.sdf"), box_segments, 0.1)
        assert found.shape == b.walls.shape and np.abs(found - b.walls).max() < 0.01, plan.name
