"""``realistic-indoor train`` and ``experiments/train_ppo.py``: paths checked first, defaults under runs/."""

from __future__ import annotations

import hashlib
import importlib.util
import json
from pathlib import Path

import pytest

from realistic_indoor.agents.rl.config import PPO_EVAL_PRESETS, EvalPlan, env_ids_of
from realistic_indoor.cli import main
from realistic_indoor.cli.train import default_model_path, envs_label
from realistic_indoor.errors import ConfigError

ROOT = Path(__file__).resolve().parents[2]
COMMITTED_MODELS = sorted(p for p in (ROOT / "experiments" / "results").rglob("ppo_*") if p.is_file())
"""The committed PPO models and their files, in the results folder and the folders below it."""


def _digests(paths: list[Path]) -> dict[str, str]:
    return {str(p.relative_to(ROOT)): hashlib.sha256(p.read_bytes()).hexdigest() for p in paths}


@pytest.fixture
def no_training(monkeypatch):
    """Training fails the test: the checks must refuse before it starts."""

    def fail(*args, **kwargs):
        raise AssertionError("training started")

    monkeypatch.setattr("realistic_indoor.agents.rl.train.train_ppo", fail)


def _one_line_error(capsys, code: int) -> str:
    assert code == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("realistic-indoor train: error: ")
    return err[0]


def test_train__smoke_preset_end_to_end_writes_under_runs(tmp_path, monkeypatch, capsys):
    pytest.importorskip("stable_baselines3")
    before = _digests(COMMITTED_MODELS)
    monkeypatch.chdir(tmp_path)
    assert main(["train", "--preset", "smoke", "--quiet", "--workers", "1"]) == 0
    out = capsys.readouterr().out
    model = tmp_path / "runs" / "ppo_realistic_smoke.zip"
    assert model.is_file() and f"saved {Path('runs/ppo_realistic_smoke.zip')}" in out
    meta = json.loads(model.with_suffix(".json").read_text())
    assert meta["timesteps"] >= 256 and meta["curve"][-1]["timesteps"] == meta["timesteps"]
    assert "1 episode per id" in out and "(--eval-episodes to change, 0 to skip)" in out
    summary = (tmp_path / "runs" / "ppo_realistic_smoke_eval" / "summary.csv").read_text()
    assert summary.count("\n") == 1 + 3 * 3  # header, 3 agents x 3 ids
    assert sorted(p.name for p in tmp_path.iterdir()) == ["runs"]
    assert _digests(COMMITTED_MODELS) == before  # the committed models are untouched
    # A second default run takes a new name; an explicit --out that exists is refused.
    assert default_model_path("realistic", "smoke") == Path("runs/ppo_realistic_smoke_2.zip")
    code = main(["train", "--preset", "smoke", "--out", str(model), "--eval-episodes", "0"])
    assert "add --overwrite" in _one_line_error(capsys, code)


@pytest.mark.parametrize(
    ("out", "message"),
    [
        (".", "is a folder"),
        ("model.pt", "unknown file type; use one of .zip"),
        ("file.txt/model.zip", "is a file, not a folder"),
    ],
)
def test_train__bad_out_is_refused_before_training(tmp_path, monkeypatch, capsys, no_training, out, message):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "file.txt").write_text("x")
    code = main(["train", "--preset", "smoke", "--out", out])
    assert message in _one_line_error(capsys, code)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--envs", "MazeExplore-v0"], "--envs: unknown id 'MazeExplore-v0'"),
        (["--envs", ","], "--envs: no id given"),
        (["--eval-envs", "Nope-v0"], "--eval-envs: unknown id 'Nope-v0'"),
        (["--timesteps", "0"], "--timesteps must be an integer >= 1, not 0"),
        (["--eval-episodes", "-1"], "--eval-episodes must be an integer >= 0"),
        (["--seed", "-3"], "--seed must be an integer >= 0"),
        (["--no-train", "--out", "missing.zip"], "--no-train evaluates the model at --out"),
        (["--eval-out", "file.txt"], "--eval-out file.txt: file.txt is a file"),
        (["--teacher", "utility"], "--teacher is for the learned presets (a rule to clone), not smoke"),
    ],
)
def test_train__bad_options_are_one_line_errors(tmp_path, monkeypatch, capsys, no_training, args, message):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "file.txt").write_text("x")
    code = main(["train", "--preset", "smoke", *args])
    assert message in _one_line_error(capsys, code)
    assert not (tmp_path / "runs").exists()


def test_train__existing_model_is_replaced_only_with_overwrite(tmp_path, monkeypatch, capsys):
    from realistic_indoor.agents.rl.train import TrainResult

    calls = []

    def fake_train(config, path, **kwargs):
        calls.append(path)
        return TrainResult(path, config.total_timesteps, 1.0, 0, float("nan"))

    monkeypatch.setattr("realistic_indoor.agents.rl.train.require_rl", lambda: None)
    monkeypatch.setattr("realistic_indoor.agents.rl.train.train_ppo", fake_train)
    model = tmp_path / "m.zip"
    model.with_suffix(".json").write_text("{}")
    code = main(["train", "--out", str(model), "--eval-episodes", "0"])
    assert "m.json exists; add --overwrite" in _one_line_error(capsys, code)
    assert main(["train", "--out", str(model), "--eval-episodes", "0", "--overwrite"]) == 0
    assert calls == [model] and "no evaluation (--eval-episodes 0)" in capsys.readouterr().out


def test_train_ppo_script__is_the_train_command_with_the_same_defaults(tmp_path, monkeypatch, capsys):
    spec = importlib.util.spec_from_file_location("train_ppo_script", ROOT / "experiments" / "train_ppo.py")
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    args = script.parse_args(["--preset", "smoke"])
    assert args.out is None and args.overwrite is False  # never the committed experiments/results
    monkeypatch.chdir(tmp_path)
    (tmp_path / "runs").mkdir()
    with pytest.raises(ConfigError, match="is a folder"):
        script.main(["--preset", "smoke", "--out", "runs"])


def test_default_model_path__never_reuses_a_name(tmp_path):
    assert default_model_path("random", "default", tmp_path) == tmp_path / "ppo_random_default.zip"
    (tmp_path / "ppo_random_default_eval").mkdir()
    assert default_model_path("random", "default", tmp_path) == tmp_path / "ppo_random_default_2.zip"
    assert default_model_path("random", "default", tmp_path, new=False).name == "ppo_random_default.zip"
    ids = env_ids_of("HouseExplore-v0, OfficeExplore-v0,HouseExplore-v0")
    assert ids == ("HouseExplore-v0", "OfficeExplore-v0")
    assert envs_label("HouseExplore-v0,OfficeExplore-v0", ids) == "houseexplore-officeexplore"
    assert env_ids_of("realistic") == ("OfficeExplore-v0", "SchoolExplore-v0", "HouseExplore-v0")


def test_eval_plans__smoke_is_tiny_and_checked():
    smoke = PPO_EVAL_PRESETS["smoke"]
    assert smoke.episodes == 1 and smoke.max_steps <= 100 and smoke.areas_m2 is not None
    assert PPO_EVAL_PRESETS["default"].max_steps is None  # the ids' own step limits
    assert smoke.describe() == "1 episode per id (at most 50 steps, training-size buildings)"
    with pytest.raises(ConfigError, match=r"EvalPlan\.episodes"):
        EvalPlan(episodes=-1)
    with pytest.raises(ConfigError, match="areas_m2"):
        EvalPlan(episodes=1, areas_m2={"office": 0.0})


def test_train__teacher_without_training_is_a_one_line_error(tmp_path, monkeypatch, capsys, no_training):
    monkeypatch.chdir(tmp_path)
    code = main(["train", "--preset", "learned-smoke", "--no-train", "--teacher", "utility"])
    assert "--teacher chooses the rule a training clones; with --no-train" in _one_line_error(capsys, code)
