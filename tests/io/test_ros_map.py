import math

import numpy as np
import pytest

from realistic_indoor.building import Building, Door, Room
from realistic_indoor.errors import ConfigError
from realistic_indoor.io import save
from realistic_indoor.sim.raster import RASTER_FREE, RASTER_OUTSIDE, RASTER_WALL, rasterize

FREE_PX, WALL_PX, UNKNOWN_PX = 254, 0, 205


def _read_pgm(path):
    """Parse a binary (P5) PGM: header tokens, comments allowed, then 8-bit pixels."""
    data = path.read_bytes()
    tokens, pos = [], 0
    while len(tokens) < 4:
        while data[pos : pos + 1].isspace():
            pos += 1
        if data[pos : pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end : end + 1].isspace():
            end += 1
        tokens.append(data[pos:end].decode("ascii"))
        pos = end
    magic, width, height, maxval = tokens[0], int(tokens[1]), int(tokens[2]), int(tokens[3])
    assert magic == "P5" and maxval == 255
    pixels = np.frombuffer(data[pos + 1 :], dtype=np.uint8)
    assert pixels.size == width * height, "pixel data must be exactly width * height bytes"
    return pixels.reshape(height, width)


def _read_yaml(path):
    """The flat ``key: value`` YAML map_server uses (numbers, words and one flow list)."""
    out = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        key, value = (s.strip() for s in line.split(":", 1))
        if value.startswith("["):
            out[key] = [float(v) for v in value.strip("[]").split(",")]
        else:
            try:
                out[key] = float(value) if "." in value else int(value)
            except ValueError:
                out[key] = value
    return out


def _ros_pixel(meta, image, x, y):
    """Row and column map_server assigns to the world point (x, y): row 0 is the top."""
    res, (ox, oy, _yaw) = meta["resolution"], meta["origin"]
    col = math.floor((x - ox) / res)
    row = image.shape[0] - 1 - math.floor((y - oy) / res)
    return row, col


@pytest.fixture
def ros_map(tiny_office, tmp_path):
    written = save(tiny_office, tmp_path / "plan.yaml")
    image, meta = _read_pgm(tmp_path / "plan.pgm"), _read_yaml(tmp_path / "plan.yaml")
    return written, image, meta


def test_ros_map__writes_pgm_and_yaml_beside_each_other(ros_map, tmp_path):
    written, _image, meta = ros_map
    assert written == [tmp_path / "plan.pgm", tmp_path / "plan.yaml"]
    assert meta["image"] == "plan.pgm"
    assert meta["mode"] == "trinary" and meta["negate"] == 0
    assert meta["occupied_thresh"] == 0.65 and meta["free_thresh"] == 0.196


def test_ros_map__size_is_footprint_over_resolution_plus_margin(ros_map):
    _, image, meta = ros_map
    assert meta["resolution"] == 0.05
    margin = 0.5
    assert image.shape == (round((6 + 2 * margin) / 0.05), round((10 + 2 * margin) / 0.05))
    assert meta["origin"] == pytest.approx([-margin, -margin, 0.0])


def test_ros_map__rooms_free_walls_occupied_outside_unknown(ros_map):
    _, image, meta = ros_map

    def at(x, y):
        return image[_ros_pixel(meta, image, x, y)]

    assert at(2.5, 4.0) == FREE_PX and at(7.5, 4.0) == FREE_PX and at(5.0, 1.0) == FREE_PX
    assert at(1.0, 2.0) == WALL_PX and at(5.0, 4.0) == WALL_PX and at(10.0, 3.0) == WALL_PX
    assert at(-0.3, 3.0) == UNKNOWN_PX and at(5.0, 6.3) == UNKNOWN_PX
    assert set(np.unique(image)) == {WALL_PX, UNKNOWN_PX, FREE_PX}


def test_ros_map__door_gaps_are_free(ros_map):
    _, image, meta = ros_map
    for x in (2.5, 7.5):
        column = [image[_ros_pixel(meta, image, x, y)] for y in np.arange(1.8, 2.21, 0.02)]
        assert all(v == FREE_PX for v in column), f"door at x={x} must be open across the wall"
    assert image[_ros_pixel(meta, image, 0.02, 1.0)] == FREE_PX, "the entrance opens the west wall"
    assert image[_ros_pixel(meta, image, 0.02, 0.3)] == WALL_PX


def test_ros_map__pixels_match_the_raster_at_ros_coordinates(tiny_office, ros_map):
    _, image, meta = ros_map
    raster = rasterize(tiny_office)
    assert meta["origin"][:2] == pytest.approx(raster.origin, abs=1e-9)
    grey = {RASTER_FREE: FREE_PX, RASTER_WALL: WALL_PX, RASTER_OUTSIDE: UNKNOWN_PX}
    rng = np.random.default_rng(0)
    points = rng.uniform((-0.5, -0.5), (10.5, 6.5), size=(500, 2))
    values = raster.value_at(points)
    for (x, y), value in zip(points, values, strict=True):
        assert image[_ros_pixel(meta, image, x, y)] == grey[int(value)], (x, y)


def test_ros_map__map_server_thresholds_read_the_three_levels(ros_map):
    _, _image, meta = ros_map

    def trinary(pixel):  # map_server's interpretation with negate: 0
        occ = (255 - pixel) / 255
        if occ > meta["occupied_thresh"]:
            return "occupied"
        return "free" if occ < meta["free_thresh"] else "unknown"

    assert (trinary(WALL_PX), trinary(FREE_PX), trinary(UNKNOWN_PX)) == ("occupied", "free", "unknown")


def _rotated(building, degrees, with_doors=True):
    from shapely import affinity

    t = math.radians(degrees)
    c, s = math.cos(t), math.sin(t)
    rooms = tuple(
        Room.from_polygon(r.id, r.label, r.function, affinity.rotate(r.polygon, degrees, origin=(0, 0)))
        for r in building.rooms
    )
    doors = tuple(
        Door(d.id, d.room_a, d.room_b, c * d.x - s * d.y, s * d.x + c * d.y, d.width_m, d.angle_rad + t)
        for d in building.doors
    )
    return Building(building.building_type, rooms, doors if with_doors else ())


@pytest.mark.parametrize("degrees", [0, 30, 45])
def test_ros_map__walls_do_not_leak_diagonally(tiny_office, tmp_path, degrees):
    from scipy import ndimage

    def free_regions(building):
        save(building, tmp_path / "m.pgm")
        free = _read_pgm(tmp_path / "m.pgm") == FREE_PX
        return ndimage.label(free, structure=np.ones((3, 3)))[1]

    assert free_regions(_rotated(tiny_office, degrees, with_doors=False)) == 3
    assert free_regions(_rotated(tiny_office, degrees)) == 1


def test_ros_map__resolution_option_and_pgm_path(tiny_office, tmp_path):
    written = save(tiny_office, tmp_path / "coarse.v2.pgm", resolution_m=0.1, margin_m=0.0)
    assert written == [tmp_path / "coarse.v2.pgm", tmp_path / "coarse.v2.yaml"]
    image, meta = _read_pgm(written[0]), _read_yaml(written[1])
    assert meta["resolution"] == 0.1 and meta["image"] == "coarse.v2.pgm"
    assert image.shape == (60, 100)


def test_ros_map__bad_resolution_is_a_config_error(tiny_office, tmp_path):
    with pytest.raises(ConfigError, match="resolution_m"):
        save(tiny_office, tmp_path / "m.yaml", resolution_m=-1.0)


@pytest.mark.parametrize("plan", ["office/Off-2.xml", "school/stjoseph'scatholichighschool_updated.xml"])
def test_ros_map__real_plan_navigable_through_every_door(real_plans_dir, tmp_path, plan):
    from scipy import ndimage

    from realistic_indoor.io import load

    building = load(real_plans_dir / plan)
    image_path, yaml_path = save(building, tmp_path / "real.yaml")
    image, meta = _read_pgm(image_path), _read_yaml(yaml_path)
    regions, _ = ndimage.label(image == FREE_PX, structure=np.ones((3, 3)))
    region = {}
    for room in building.rooms:
        p = room.polygon.representative_point()
        region[room.id] = regions[_ros_pixel(meta, image, p.x, p.y)]
    assert all(region.values()), "every room's interior is free"
    blocked = [d.id for d in building.doors if not d.is_exterior and region[d.room_a] != region[d.room_b]]
    assert not blocked, f"doors closed on the map: {blocked[:5]}"
