"""``realistic-indoor generate --like``: twins of a folder of plans, bad plans skipped and counted."""

from __future__ import annotations

import pytest

import realistic_indoor as ri
from realistic_indoor.cli import main


@pytest.fixture
def plans(tmp_path):
    folder = tmp_path / "plans"
    ri.save(ri.generate("office", area_m2=900, seed=1), folder / "small.json")
    ri.save(ri.generate("office", area_m2=2500, seed=2), folder / "large.json")
    ri.save(ri.generate("school", area_m2=1500, seed=3), folder / "school.json")
    (folder / "broken.xml").write_text("", encoding="utf-8")
    return folder


def test_generate_like__one_twin_per_office_plan_with_its_area(plans, tmp_path, capsys):
    out = tmp_path / "twins"
    assert main(["generate", "--type", "office", "--like", str(plans), "--out-dir", str(out)]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["large.json", "small.json"]
    for name in ("small", "large"):
        plan, twin = ri.load(plans / f"{name}.json"), ri.load(out / f"{name}.json")
        assert twin.area == pytest.approx(plan.area, rel=0.02)
        assert twin.metadata["like"]["plan"] == name
    captured = capsys.readouterr()
    assert "wrote 2 office buildings like 2 plans" in captured.out
    assert "skipped 2 of 4 plans: broken.xml, school.json" in captured.err


def test_generate_like__strict_stops_at_the_broken_plan(plans, tmp_path, capsys):
    code = main(["generate", "--like", str(plans), "--out-dir", str(tmp_path / "t"), "--strict"])
    err = capsys.readouterr().err.strip()
    assert code == 1 and "broken.xml" in err and len(err.splitlines()) == 1


def test_generate_like__count_and_seed_name_and_repeat_the_twins(plans, tmp_path):
    args = ["generate", "--like", str(plans / "small.json"), "--count", "2", "--seed", "4"]
    assert main([*args, "--out-dir", str(tmp_path / "a")]) == 0
    assert main([*args, "--out-dir", str(tmp_path / "b")]) == 0
    assert sorted(p.name for p in (tmp_path / "a").iterdir()) == ["small_0.json", "small_1.json"]
    assert (tmp_path / "a/small_1.json").read_bytes() == (tmp_path / "b/small_1.json").read_bytes()


@pytest.mark.parametrize(
    ("extra", "message"),
    [(["-o", "x.json"], "not -o"), ([], "--out-dir"), (["--out-dir", "o", "--count", "0"], "--count")],
)
def test_generate_like__bad_arguments_are_one_line(plans, capsys, extra, message):
    assert main(["generate", "--like", str(plans), *extra]) == 1
    err = capsys.readouterr().err.strip()
    assert message in err and len(err.splitlines()) == 1


def test_generate_like__folder_without_plans_is_an_error(tmp_path, capsys):
    (tmp_path / "empty").mkdir()
    assert main(["generate", "--like", str(tmp_path / "empty"), "--out-dir", str(tmp_path / "o")]) == 1
    assert "no plans there" in capsys.readouterr().err


def test_generate_like__model_and_layout_reach_the_generator(plans, tmp_path):
    out = tmp_path / "paper"
    args = ["generate", "--type", "office", "--like", str(plans), "--out-dir", str(out), "--model", "paper"]
    assert main(args) == 0
    twin = ri.load(out / "small.json")
    assert twin.metadata["params"]["model"] == "office"  # the paper's model is named in the metadata
    assert not twin.metadata["shape"].startswith(("double-loaded", "ring"))  # the wing layout's shapes
