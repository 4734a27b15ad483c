import csv
import io
import json

import pytest

from realistic_indoor.errors import ConfigError
from realistic_indoor.models import reference_table
from realistic_indoor.validator.compare import compare_sets
from realistic_indoor.validator.plan_sets import PlanSet
from realistic_indoor.validator.report import render_comparison
from realistic_indoor.validator.tables import label_table, render_label_tables


@pytest.fixture
def comparison(maze_office, tiny_office, scaled):
    mazes = PlanSet.of("mazes", [scaled(maze_office, f) for f in (0.9, 1.0, 1.1)])
    tidy = PlanSet.of("tidy", [scaled(tiny_office, f) for f in (0.9, 1.0, 1.1)])
    return compare_sets([mazes, tidy], "office")


def test_render_label_tables__side_by_side_with_the_reference(maze_office):
    text = render_label_tables({"maze": label_table([maze_office]), "paper": reference_table("office")})
    lines = text.splitlines()
    assert lines[0].split() == ["label", "statistic", "maze", "paper"]
    corridor_doors = next(line for line in lines if "doorways" in line)
    assert corridor_doors.split()[-6:] == ["3.5", "±", "2.5", "6.7", "±", "4.8"]
    assert "25.0% (2)" in text and "20.6%" in text


def test_render_label_tables__markdown_csv_json(maze_office):
    tables = {"maze": label_table([maze_office])}
    md = render_label_tables(tables, "markdown", title="T")
    assert md.splitlines()[0] == "### T"
    assert "| corridor | rooms (%) | 25.0% (2) |" in md
    rows = list(csv.DictReader(io.StringIO(render_label_tables(tables, "csv"))))
    assert {"set": "maze", "label": "medium", "statistic": "area_mean", "value": "17.6"} in rows
    assert next(r for r in rows if r["label"] == "hall" and r["statistic"] == "area_mean")["value"] == ""
    data = json.loads(render_label_tables(tables, "json"))
    assert data["maze"]["corridor"]["doors_mean"] == 3.5
    assert data["maze"]["hall"]["area_mean"] is None


def test_render_label_tables__unknown_format(maze_office):
    with pytest.raises(ConfigError, match="unknown table format 'html'"):
        render_label_tables({"maze": label_table([maze_office])}, "html")


def test_render_comparison__terminal_report_has_every_section(comparison):
    text = render_comparison(comparison)
    for heading in ("Table 1", "Connectivity", "Realism score", "Two-sample tests", "Worst deviations:"):
        assert heading in text
    assert "60% of offices touch a corridor; real offices 98%" in text
    assert "mazes vs tidy" in text
    line = next(ln for ln in text.splitlines() if ln.startswith("core rooms touching a corridor ("))
    assert line.split()[-3:] == ["60.0", "100.0", "98.0"]


def test_render_comparison__markdown_json_csv_agree(comparison):
    md = render_comparison(comparison, "markdown")
    assert md.startswith("## Realism of 2 sets of office plans against real offices")
    data = json.loads(render_comparison(comparison, "json"))
    assert [s["name"] for s in data["sets"]] == ["mazes", "tidy"]
    assert data["sets"][0]["score"]["overall"] == pytest.approx(comparison.sets[0].score.overall)
    assert data["two_sample"][0]["accuracy"] == pytest.approx(1.0)
    rows = list(csv.DictReader(io.StringIO(render_comparison(comparison, "csv"))))
    overall = next(
        r for r in rows if r["section"] == "score" and r["set"] == "tidy" and r["statistic"] == "overall"
    )
    assert float(overall["value"]) == pytest.approx(comparison.sets[1].score.overall)
    assert {r["section"] for r in rows} == {"table", "connectivity", "building", "score", "two_sample"}


def test_render_comparison__unknown_format(comparison):
    with pytest.raises(ConfigError, match="unknown report format 'xml'"):
        render_comparison(comparison, "xml")
