import math

import numpy as np
import pytest

from realistic_indoor.building import Building, Door, Room, SemanticLabel
from realistic_indoor.errors import ConfigError
from realistic_indoor.io import save
from realistic_indoor.io.render import DEFAULT_STYLE, LABEL_COLOURS, draw_plan, plan_figure, render_array


def _rgb(hex_colour: str) -> np.ndarray:
    return np.array([int(hex_colour[i : i + 2], 16) for i in (1, 3, 5)])


def _pixel(fig, x: float, y: float) -> np.ndarray:
    """RGB of the drawn figure at the world point (x, y) metres."""
    image = np.asarray(fig.canvas.buffer_rgba())[..., :3]
    col, row = fig.axes[0].transData.transform((x, y))
    return image[int(image.shape[0] - row), int(col)].astype(int)


def _close(pixel: np.ndarray, hex_colour: str, tol: int = 12) -> bool:
    return bool(np.abs(pixel - _rgb(hex_colour)).max() <= tol)


def _grid_building(n_corridors: int, rooms_per_side: int) -> Building:
    """Rows of rooms on both sides of parallel corridors; every label used."""
    labels = ("small", "medium", "big", "hall")
    rooms, doors = [], []
    for j in range(n_corridors):
        y = j * 14.5
        cid = f"c{j}"
        rooms.append(Room.rectangle(cid, "corridor", "corridor", (0, y + 6, rooms_per_side * 4, y + 8.5)))
        for side, (ya, yb, yd) in enumerate(((y, y + 6, y + 6), (y + 8.5, y + 14.5, y + 8.5))):
            for i in range(rooms_per_side):
                rid = f"r{j}_{side}_{i}"
                label = labels[(i + j + side) % len(labels)]
                rooms.append(Room.rectangle(rid, label, "office", (i * 4, ya, i * 4 + 4, yb)))
                doors.append(Door(f"d_{rid}", rid, cid, i * 4 + 2, yd, 0.9, 0.0))
    doors.append(Door("e", "c0", None, 0.0, 7.25, 1.2, math.pi / 2))
    return Building("school", tuple(rooms), tuple(doors), {"generator": "grid"})


def test_render__rooms_filled_by_label_walls_and_doors_drawn(tiny_office):
    fig = plan_figure(tiny_office, dpi=200)
    fig.canvas.draw()
    assert _close(_pixel(fig, 2.5, 4.0), LABEL_COLOURS[SemanticLabel.MEDIUM])
    assert _close(_pixel(fig, 5.0, 1.0), LABEL_COLOURS[SemanticLabel.CORRIDOR])
    assert _close(_pixel(fig, 1.0, 2.0), DEFAULT_STYLE.wall_colour)
    assert _close(_pixel(fig, 5.0, 4.0), DEFAULT_STYLE.wall_colour)
    assert _close(_pixel(fig, 2.5, 2.0), DEFAULT_STYLE.door_colour)
    assert _close(_pixel(fig, 7.5, 2.0), DEFAULT_STYLE.door_colour)
    assert _close(_pixel(fig, 0.0, 1.0), DEFAULT_STYLE.entrance_colour)


def test_render__entrance_marker_points_inside(tiny_office):
    fig = plan_figure(tiny_office, dpi=200)
    fig.canvas.draw()
    (marker,) = fig.axes[0].lines
    x_disp, _ = marker.get_transform().transform((0.0, 1.0))
    door_disp, _ = fig.axes[0].transData.transform((0.0, 1.0))
    assert x_disp > door_disp, "the entrance is on the west wall: its triangle sits east of it"


def test_render__png_holds_render_array_pixels(tiny_office, tmp_path):
    import matplotlib.image as mpimg

    path = tmp_path / "plan.png"
    assert save(tiny_office, path, dpi=80) == [path]
    png = (mpimg.imread(path)[..., :3] * 255).round().astype(np.uint8)
    array = render_array(tiny_office, dpi=80)
    assert array.dtype == np.uint8 and array.ndim == 3 and array.shape[2] == 3
    np.testing.assert_array_equal(png, array)


@pytest.mark.parametrize("suffix", [".png", ".svg"])
def test_render__same_plan_same_bytes(tiny_office, tmp_path, suffix):
    a, b = tmp_path / f"a{suffix}", tmp_path / f"b{suffix}"
    save(tiny_office, a, dpi=60)
    save(tiny_office, b, dpi=60)
    assert a.read_bytes() == b.read_bytes()


def test_render__svg_is_vector_with_legend(tiny_office, tmp_path):
    path = tmp_path / "plan.svg"
    save(tiny_office, path)
    text = path.read_text(encoding="utf-8")
    assert text.lstrip().startswith("<?xml") and "<svg" in text
    assert "<image" not in text, "an SVG plan is drawn with vector paths, not an embedded bitmap"


def test_render__legend_lists_every_label_with_counts(tiny_office):
    ax = draw_plan(tiny_office)
    texts = [t.get_text() for t in ax.get_legend().get_texts()]
    assert texts[:5] == ["corridor (1)", "hall (0)", "small (0)", "medium (2)", "big (0)"]
    assert {"wall", "door", "entrance"} <= set(texts)


def test_render__title_automatic_custom_or_none(tiny_office):
    auto = draw_plan(tiny_office).get_title(loc="left")
    assert (
        "generator: hand-made" in auto
        and "3 rooms" in auto
        and "3 doors (1 exterior)" in auto
        and "60 m²" in auto
    )
    assert draw_plan(tiny_office, title="Ground floor").get_title(loc="left") == "Ground floor"
    assert draw_plan(tiny_office, title=False).get_title(loc="left") == ""


def test_render__draws_on_the_callers_axes(tiny_office):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure()
    FigureCanvasAgg(fig)
    left, right = fig.subplots(1, 2)
    assert draw_plan(tiny_office, right, legend=False, scale_bar=False) is right
    assert len(right.collections) == 4  # rooms, walls, doors, entrances
    assert not left.collections
    assert right.get_legend() is None
    assert right.get_aspect() == 1.0


def test_render__function_labels_only_where_they_fit(tiny_office):
    ax = draw_plan(tiny_office, show_functions=True, legend=False)
    assert sorted(t.get_text() for t in ax.texts) == ["corridor", "office", "office"]
    small = plan_figure(tiny_office, size_in=0.5, show_functions=True, legend=False, title=False)
    assert not small.axes[0].texts


def test_render__scale_bar_length_is_round():
    from realistic_indoor.io.render.decorations import nice_length

    assert nice_length(10.0) == 2.0
    assert nice_length(147.0) == 20.0
    assert nice_length(260.0) == 50.0
    assert nice_length(0.8) == pytest.approx(0.1)


def test_render__many_rooms_every_label_colour_shows():
    building = _grid_building(4, 12)
    image = render_array(building, size_in=5, dpi=80, legend=False, title=False, scale_bar=False)
    flat = image.reshape(-1, 3).astype(int)
    for label, colour in LABEL_COLOURS.items():
        if label is not SemanticLabel.BIG or building.label_counts()[label]:
            assert (np.abs(flat - _rgb(colour)).max(axis=1) <= 2).any(), label


def test_render__empty_building_draws_without_error():
    image = render_array(Building("unknown", ()), size_in=2, dpi=50)
    assert image.shape[2] == 3 and image.size > 0


def test_render__wrong_extension_or_size_is_a_config_error(tiny_office, tmp_path):
    from realistic_indoor.io.render import write

    with pytest.raises(ConfigError, match=r"\.png or \.svg"):
        write(tiny_office, tmp_path / "plan.jpg")
    with pytest.raises(ConfigError, match=r"size_in must be a finite number in \[0\.5, 200\] inches, got 0"):
        render_array(tiny_office, size_in=0)
    with pytest.raises(ConfigError, match=r"dpi must be a finite number in \[10, 2400\]"):
        render_array(tiny_office, dpi=1e-300)


def test_render__title_names_the_plan(tiny_office):
    from dataclasses import replace

    from realistic_indoor.io.render.decorations import auto_title

    named = replace(tiny_office, metadata={"name": "Off-2", "source": "/data/plans/other.xml"})
    assert auto_title(named).splitlines()[0] == "Off-2"
    from_file = replace(tiny_office, metadata={"source": "/data/plans/Off-3.xml"})
    assert auto_title(from_file).splitlines()[0] == "Off-3"
    generated = replace(tiny_office, metadata={"generator": "office", "seed": 7})
    assert auto_title(generated).splitlines()[0] == "generator: office, seed 7"


def test_render__every_shared_real_plan(real_plans_dir):
    from realistic_indoor.io import load

    plans = sorted(real_plans_dir.glob("*/*.xml"))
    assert len(plans) >= 50
    for plan in plans:
        building = load(plan, infer_entrances=True)
        image = render_array(building, size_in=3, dpi=30, title=False, legend=False)
        assert image.shape[2] == 3 and max(image.shape[:2]) >= 3 * 30, plan.name
        fill = _rgb(LABEL_COLOURS[building.rooms[0].label])
        assert (np.abs(image.reshape(-1, 3).astype(int) - fill).max(axis=1) <= 2).any(), plan.name
