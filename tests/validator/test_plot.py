from realistic_indoor.validator.compare import compare_sets
from realistic_indoor.validator.plan_sets import PlanSet
from realistic_indoor.validator.plot import comparison_figure, plot_comparison

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def test_comparison_figure__eight_panels_with_the_reference(maze_office, tiny_office):
    c = compare_sets(
        [PlanSet.of("mazes", [maze_office] * 2), PlanSet.of("tidy", [tiny_office] * 2)], "office"
    )
    fig = comparison_figure(c)
    titles = [ax.get_title(loc="left") for ax in fig.axes]
    assert titles == [
        "Share of rooms per label",
        "Room area per label",
        "Axes ratio per label",
        "Building: footprint, circulation, depth",
        "Connectivity",
        "Doorways per label",
        "Realism score vs paper: office",
        "Building: room density",
    ]
    legend = [t.get_text() for t in fig.legends[0].get_texts()]
    assert legend == ["mazes (2)", "tidy (2)", "paper: office: shares", "paper: office: mean ± std"]


def test_plot_comparison__writes_a_png_with_a_fitted_reference(maze_office, tiny_office, tmp_path):
    c = compare_sets(
        [PlanSet.of("mazes", [maze_office] * 2)], "office", reference=PlanSet.of("real", [tiny_office] * 2)
    )
    out = plot_comparison(c, tmp_path / "figs" / "cmp.png")
    assert out.read_bytes()[:8] == PNG_MAGIC
    legend = [t.get_text() for t in comparison_figure(c).legends[0].get_texts()]
    assert legend == ["mazes (2)", "real (2)", "real: connectivity"]
