import json

import pytest

from realistic_indoor.cli import main
from realistic_indoor.generator import generate
from realistic_indoor.io import load
from realistic_indoor.io.json_format import dumps
from realistic_indoor.models import fit_model

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def _error_line(err: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


def test_cli_generate__writes_the_building_and_its_picture(tmp_path, capsys):
    out, png = tmp_path / "school.json", tmp_path / "school.png"
    assert (
        main(
            [
                "generate",
                "--type",
                "school",
                "--area",
                "1500",
                "--seed",
                "7",
                "-o",
                str(out),
                "--png",
                str(png),
            ]
        )
        == 0
    )
    b = load(out)
    assert b.metadata["seed"] == 7 and b.building_type.value == "school"
    assert dumps(b) == dumps(generate("school", 1500, seed=7))
    assert png.read_bytes()[:8] == PNG_MAGIC
    assert "wrote" in capsys.readouterr().out


def test_cli_generate__count_writes_files_named_by_type_and_seed(tmp_path, capsys):
    assert (
        main(["generate", "--type", "house", "--count", "3", "--seed", "10", "--out-dir", str(tmp_path)]) == 0
    )
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["house_10.json", "house_11.json", "house_12.json"]
    assert load(tmp_path / "house_11.json").metadata["seed"] == 11
    assert "house buildings" in capsys.readouterr().err


def test_cli_generate__random_grid_from_width_and_height(tmp_path):
    out = tmp_path / "grid.json"
    assert (
        main(["generate", "--type", "random", "--width", "8", "--height", "6", "--seed", "1", "-o", str(out)])
        == 0
    )
    assert load(out).metadata["params"]["width_units"] == 8


def test_cli_generate__fitted_model_from_a_json_file(tmp_path):
    model = fit_model([generate("office", 800, seed=s) for s in range(3)], name="hospital")
    path = tmp_path / "hospital.json"
    path.write_text(json.dumps(model.to_dict()))
    out = tmp_path / "h.json"
    assert (
        main(
            [
                "generate",
                "--type",
                "office",
                "--model",
                str(path),
                "--area",
                "900",
                "--seed",
                "2",
                "-o",
                str(out),
            ]
        )
        == 0
    )
    assert load(out).metadata["params"]["model"] == "hospital"


def test_cli_generate__unknown_type_lists_the_valid_ones(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["generate", "--type", "castle"])
    assert exc.value.code == 2
    assert "office" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["--type", "house", "--area", "10"], "smallest is 50 m2"),
        (["--area", "-3"], "positive number"),
        (["--type", "office", "--width", "4", "--height", "4"], "only with --type random"),
        (["--type", "random", "--width", "300", "--height", "6"], "from 5 to 200"),
        (["--count", "0", "--out-dir", "x"], "at least 1"),
        (["--count", "2", "-o", "x.json"], "--out-dir"),
        (["--model", "/no/such/model.json"], "cannot read the model"),
    ],
)
def test_cli_generate__bad_input_is_one_line_with_exit_code_1(argv, words, capsys):
    assert main(["generate", *argv]) == 1
    assert words in _error_line(capsys.readouterr().err)
