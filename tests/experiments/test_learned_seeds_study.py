import json
import re
import shutil
from types import SimpleNamespace

import pytest
from script_loader import load_script


def _load():
    load_script("experiments/learned_explorer.py")  # the script imports it as a sibling module
    return load_script("experiments/learned_seeds.py")


def _r(agent, env, seed, auc, group="offices"):
    return SimpleNamespace(agent=agent, env=env, group=group, seed=seed, coverage_auc=auc)


def _row(report, start):
    line = next(line for line in report.splitlines() if line.startswith(start))
    return [c.strip() for c in line.strip("|").split("|")]


def test_report__kinds_average_their_seeds_per_building_before_pairing():
    """Hand-made results: two realistic seeds, one random seed, frontier; two buildings."""
    module = _load()
    results = [
        _r("learned_realistic_seed0", "o", 1, 0.80), _r("learned_realistic_seed0", "o", 2, 0.60),
        _r("learned_realistic_seed1", "o", 1, 0.70), _r("learned_realistic_seed1", "o", 2, 0.80),
        _r("learned_random_seed0", "o", 1, 0.70), _r("learned_random_seed0", "o", 2, 0.70),
        _r("frontier", "o", 1, 0.70), _r("frontier", "o", 2, 0.70),
        _r("utility", "o", 1, 0.70), _r("utility", "o", 2, 0.70),
        _r("structure", "o", 1, 0.70), _r("structure", "o", 2, 0.70),
    ]  # fmt: skip
    meta = {"command": "c", "commit": "x", "baselines": "b", "episodes": 2, "seed": 1000, "sets": ["offices"]}
    report = module.analyse(results, meta)
    # realistic per building: (0.80 + 0.70) / 2 = 0.75 and (0.60 + 0.80) / 2 = 0.70
    kind = _row(report, "| offices | **realistic (2 seeds)**")
    assert kind[2:5] == ["2", "0.725", "+0.025 [+0.000, +0.050]"]
    one = _row(report, "| offices | learned_realistic_seed0")
    assert one[3:5] == ["0.700", "+0.000 [-0.100, +0.100]"]
    versus = _row(report, "| offices | 2 |")
    assert versus[2:] == ["0.725", "0.700", "+0.025 [+0.000, +0.050]"]
    assert (
        "- offices: learned minus frontier +0.025 [+0.000, +0.050], asked >= +0.010 with the interval above 0: not met"
        in report
    )
    assert "- offices: learned minus structure +0.025 [+0.000, +0.050], asked >= -0.005: met" in report


def test_models__found_by_name_realistic_first_then_by_seed(tmp_path):
    module = _load()
    for name in (
        "learned_random_seed1",
        "learned_realistic_seed2",
        "learned_random_seed0",
        "other",
        "learned_x_seed1",
    ):
        (tmp_path / f"{name}.zip").write_bytes(b"")
    assert list(module.find_models(tmp_path)) == [
        "learned_realistic_seed2",
        "learned_random_seed0",
        "learned_random_seed1",
    ]


@pytest.mark.slow
def test_small_run__the_same_model_trained_twice_differs_from_itself_by_nothing(tmp_path):
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    from realistic_indoor.agents.rl.learned_agent import DEFAULT_MODEL

    models = tmp_path / "models"
    models.mkdir()
    for name in ("learned_realistic_seed0", "learned_random_seed0"):
        shutil.copy(DEFAULT_MODEL, models / f"{name}.zip")
    out = tmp_path / "out"
    assert _load().main(["--small", "--models", str(models), "--out", str(out)]) == 0
    data = json.loads((out / "learned_seeds" / "learned_random_seed0" / "results.json").read_text())
    assert {e["agent"] for e in data["episodes"]} == {"learned_random_seed0"}
    report = (out / "learned_seeds.md").read_text()
    assert _row(report, "| houses | 2 |")[4] == "+0.000 [+0.000, +0.000]"
    assert "| houses | **random (1 seed)** | 2 |" in report


def test_ppo_track__its_own_models_agent_and_labels(tmp_path):
    module = _load()
    track = module.TRACKS["ppo-global-map"]
    for name in ("ppo_global_random_seed0", "ppo_global_realistic_seed0", "learned_realistic_seed1"):
        (tmp_path / f"{name}.zip").write_bytes(b"")
    assert list(module.find_models(tmp_path, track)) == [
        "ppo_global_realistic_seed0",
        "ppo_global_random_seed0",
    ]
    assert track.agent == "ppo"
    results = [
        _r("ppo_global_realistic_seed0", "o", 1, 0.30), _r("ppo_global_realistic_seed0", "o", 2, 0.50),
        _r("ppo_global_random_seed0", "o", 1, 0.20), _r("ppo_global_random_seed0", "o", 2, 0.20),
        _r("frontier", "o", 1, 0.70), _r("frontier", "o", 2, 0.70),
    ]  # fmt: skip
    meta = {"command": "c", "commit": "x", "baselines": "b", "episodes": 2, "seed": 1000, "sets": ["offices"]}
    report = module.analyse(results, {**meta, "track": "ppo-global-map"})
    assert report.startswith("# Primitive-action PPO with the global map")
    assert _row(report, "| offices | 2 |")[2:] == ["0.400", "0.200", "+0.200 [+0.100, +0.300] *"]
    assert "- offices: PPO (global map) minus frontier -0.300 [-0.400, -0.200]" in report


def test_structure_utility_track__takes_its_own_models_and_refuses_another_rules(tmp_path):
    from realistic_indoor.errors import ConfigError

    module = _load()
    track = module.TRACKS["learned-structure-utility"]
    for name in ("learned_su_realistic_seed0", "learned_realistic_seed1"):
        (tmp_path / f"{name}.zip").write_bytes(b"")
    meta = tmp_path / "learned_su_realistic_seed0.json"
    meta.write_text(json.dumps({"config": {"teacher": "structure-utility"}}))
    assert list(module.find_models(tmp_path, track)) == ["learned_su_realistic_seed0"]
    assert track.agent == "learned"
    meta.write_text(json.dumps({"config": {"teacher": "structure"}}))
    with pytest.raises(
        ConfigError,
        match=r"trained with teacher 'structure', which the learned_su models are not \(teacher "
        r"'structure-utility'\); .* "
        "--preset learned-one-rule --teacher structure-utility",
    ):
        module.find_models(tmp_path, track)
    meta.write_text(json.dumps({"config": {}}))  # a model from before the option cloned structure
    with pytest.raises(ConfigError, match="trained with teacher 'structure',"):
        module.find_models(tmp_path, track)


def test_recipe_track__its_seed_0_model_is_the_package_one(tmp_path):
    from realistic_indoor.agents.rl.learned import learned_preset
    from realistic_indoor.agents.rl.learned_agent import DEFAULT_MODEL
    from realistic_indoor.agents.rl.teachers import DEFAULT_TEACHER
    from realistic_indoor.errors import ConfigError

    module = _load()
    track = module.TRACKS["learned-pooled"]
    assert track.teacher == DEFAULT_TEACHER and track.recipe == "learned"
    meta = tmp_path / "learned_pool_realistic_seed0.json"
    meta.write_text(json.dumps({"config": learned_preset("learned").to_dict()}))
    (tmp_path / "learned_pool_random_seed0.zip").write_bytes(b"")
    found = module.find_models(tmp_path, track)
    assert list(found) == ["learned_pool_realistic_seed0", "learned_pool_random_seed0"]
    assert found["learned_pool_realistic_seed0"] == DEFAULT_MODEL
    # a model of the recipe before (same rules, no pooled summary, no balance) belongs to its own track
    meta.write_text(json.dumps({"config": learned_preset("learned-house-rule").to_dict()}))
    with pytest.raises(
        ConfigError,
        match=r"with scorer_pool 0, bc_balance False, which the learned_pool models are not \(scorer_pool 16, bc_balance True\); .* --preset learned$",
    ):
        module.find_models(tmp_path, track)
    # and the other way: the house-rule track refuses the recipe's model and the one-rule recipe's
    hr = module.TRACKS["learned-house-rule"]
    (tmp_path / "learned_hr_realistic_seed0.zip").write_bytes(b"")
    hr_meta = tmp_path / "learned_hr_realistic_seed0.json"
    hr_meta.write_text(json.dumps({"config": learned_preset("learned-house-rule").to_dict()}))
    assert list(module.find_models(tmp_path, hr)) == ["learned_hr_realistic_seed0"]
    for preset, differ in (
        ("learned", "scorer_pool 16, bc_balance True"),
        ("learned-one-rule", "teacher_by_id [], scorer_context False"),
    ):
        hr_meta.write_text(json.dumps({"config": learned_preset(preset).to_dict()}))
        with pytest.raises(
            ConfigError, match=f"with {re.escape(differ)}, which the learned_hr models are not"
        ):
            module.find_models(tmp_path, hr)
    suas = module.TRACKS["learned-structure-utility-area-short"]
    (tmp_path / "learned_suas_realistic_seed0.json").write_text(
        json.dumps({"config": learned_preset("learned").to_dict()})
    )
    (tmp_path / "learned_suas_realistic_seed0.zip").write_bytes(b"")
    with pytest.raises(
        ConfigError, match=r"teacher_by_id \[\['HouseExplore-v0', 'gain'\]\], .* learned_suas models"
    ):
        module.find_models(tmp_path, suas)
    # the earlier recipes' tracks have no committed model any more: their seed-0 models lie in
    # their folders
    for name in (
        "learned",
        "learned-structure-utility-area",
        "learned-structure-utility-area-short",
        "learned-house-rule",
    ):
        assert module.TRACKS[name].committed == {}
        found = module.find_models(module.TRACKS[name].models, module.TRACKS[name])
        seed0 = next(path for model, path in found.items() if model.endswith("_realistic_seed0"))
        assert seed0.parent == module.TRACKS[name].models
