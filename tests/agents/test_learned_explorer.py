"""The learned explorer: its teacher rules, its agent loop, its model files and its training command.

Expected values are worked out by hand (the teacher rules on hand-made candidates) or come from
the classical explorer (a policy that always chooses candidate 0 is the nearest-frontier
explorer, whichever side of the environment runs the macro actions).
"""

from __future__ import annotations

import json
import subprocess
import sys

import gymnasium as gym
import numpy as np
import pytest
from agent_helpers import AlwaysChoose

from realistic_indoor.agents import make_agent
from realistic_indoor.agents.rl.teachers import TEACHERS, TeacherPolicy, teacher_choice
from realistic_indoor.envs.macro import CANDIDATE_FEATURES
from realistic_indoor.errors import ConfigError

F = len(CANDIDATE_FEATURES)


def _rows(*candidates: dict) -> tuple[np.ndarray, np.ndarray]:
    """Flat candidates of K = 4 from dicts of features, and their mask."""
    rows = np.zeros((4, F), dtype=np.float32)
    for i, features in enumerate(candidates):
        rows[i, 0] = 1.0
        for name, value in features.items():
            rows[i, CANDIDATE_FEATURES.index(name)] = value
    return rows.ravel(), rows[:, 0] == 1.0


def test_structure_rule__prefers_the_circulation_unless_a_room_is_four_times_nearer():
    # costs 1.0 (room), 3.0 (corridor), 3.5 (corridor): weighted 4.0, 3.0, 3.5 -> the corridor at 3.0
    flat, mask = _rows({"path_cost": 0.1, "in_room": 1}, {"path_cost": 0.3}, {"path_cost": 0.35})
    assert teacher_choice(flat, mask, "structure") == 1
    # a room at 0.7 m (weighted 2.8) beats a corridor at 3.0 m
    flat, mask = _rows({"path_cost": 0.07, "in_room": 1}, {"path_cost": 0.3})
    assert teacher_choice(flat, mask, "structure") == 0
    # every candidate in a room: the nearest
    flat, mask = _rows({"path_cost": 0.2, "in_room": 1}, {"path_cost": 0.5, "in_room": 1})
    assert teacher_choice(flat, mask, "structure") == 0


def test_teachers__utility_trades_a_long_frontier_against_three_times_its_cost():
    # 3 * 1.0 - 0.5 = 2.5 (a short frontier at 10 m) against 3 * 1.5 - 2.5 = 2.0 (25 m long at 15 m)
    flat, mask = _rows({"path_cost": 1.0, "size": 0.5}, {"path_cost": 1.5, "size": 2.5})
    assert teacher_choice(flat, mask, "utility") == 1
    assert teacher_choice(flat, mask, "frontier") == 0  # the nearer
    # structure-utility: the same long frontier in a room costs 3 * 1.5 * 2 - 2.5 = 6.5 > 2.5
    flat, mask = _rows({"path_cost": 1.0, "size": 0.5}, {"path_cost": 1.5, "size": 2.5, "in_room": 1})
    assert teacher_choice(flat, mask, "utility") == 1
    assert teacher_choice(flat, mask, "structure-utility") == 0


def test_teacher_rule__a_gain_weight_trades_unobserved_area_against_path_cost():
    from realistic_indoor.agents.rl.teachers import TeacherRule

    # 0.5 - 1.0 * 0.2 = 0.3 (5 m, 2 m2 unseen) against 1.2 - 1.0 * 1.5 = -0.3 (12 m, 15 m2 unseen)
    flat, mask = _rows({"path_cost": 0.5, "unobserved": 0.2}, {"path_cost": 1.2, "unobserved": 1.5})
    assert TeacherRule(gain_weight=1.0).choose(flat, mask) == 1
    assert TeacherRule(gain_weight=0.5).choose(flat, mask) == 0  # 0.4 against 0.45
    assert TeacherRule().choose(flat, mask) == 0  # no gain term: the nearer


def test_teacher_rule__a_turn_weight_charges_a_goal_behind_the_robot():
    from realistic_indoor.agents.rl.teachers import TeacherRule

    # 5 m straight behind (cos -1) against 8 m straight ahead (cos 1)
    flat, mask = _rows({"path_cost": 0.5, "cos_bearing": -1.0}, {"path_cost": 0.8, "cos_bearing": 1.0})
    assert TeacherRule(turn_weight=0.5).choose(flat, mask) == 1  # 0.5 + 0.5 = 1.0 against 0.8
    assert TeacherRule(turn_weight=0.2).choose(flat, mask) == 0  # 0.5 + 0.2 = 0.7 against 0.8
    # abeam (cos 0) pays half: 0.6 + 0.25 = 0.85 against 0.8
    flat, mask = _rows({"path_cost": 0.6, "cos_bearing": 0.0}, {"path_cost": 0.8, "cos_bearing": 1.0})
    assert TeacherRule(turn_weight=0.5).choose(flat, mask) == 1
    assert TeacherRule().choose(flat, mask) == 0  # no turn term: the nearer


def test_teacher_rule__a_short_factor_puts_off_a_sliver_of_frontier():
    from realistic_indoor.agents.rl.teachers import TeacherRule

    # 5 m to a 0.5 m sliver against 8 m to a 3 m frontier (size in units of 10 m)
    flat, mask = _rows({"path_cost": 0.5, "size": 0.05}, {"path_cost": 0.8, "size": 0.3})
    assert TeacherRule(short_factor=2.0).choose(flat, mask) == 1  # 1.0 against 0.8
    assert TeacherRule(short_factor=1.5).choose(flat, mask) == 0  # 0.75 against 0.8
    assert TeacherRule(short_factor=2.0, short_m=0.4).choose(flat, mask) == 0  # 0.5 m is not short
    assert TeacherRule().choose(flat, mask) == 0  # no factor: the nearer
    # it multiplies with the room factor: a short room frontier at 2 m costs 0.2 * 2 * 2 = 0.8
    flat, mask = _rows({"path_cost": 0.2, "size": 0.05, "in_room": 1}, {"path_cost": 0.7, "size": 0.3})
    assert TeacherRule(room_factor=2.0, short_factor=2.0).choose(flat, mask) == 1
    assert TeacherRule(room_factor=2.0).choose(flat, mask) == 0  # 0.4 against 0.7


def test_teachers__are_the_classical_explorers_rules():
    from realistic_indoor.agents.structure import StructureConfig
    from realistic_indoor.agents.utility import UtilityConfig

    assert TEACHERS["structure"].room_factor == StructureConfig().room_factor
    # the recipe's rule is structure-utility-area with slivers (shorter than 1 m) at twice the cost
    from dataclasses import replace

    short = replace(TEACHERS["structure-utility-area"], short_factor=2.0, short_m=1.0)
    assert TEACHERS["structure-utility-area-short"] == short
    utility = UtilityConfig()
    assert utility.gain == "length"  # the rule's gain is the frontier's length
    assert (
        TEACHERS["utility"].cost_weight / TEACHERS["utility"].length_weight
        == utility.cost_weight / utility.gain_weight
    )


def test_teachers__an_unknown_rule_is_a_one_line_config_error():
    flat, mask = _rows({"path_cost": 0.1})
    for call in (lambda: teacher_choice(flat, mask, "oracle"), lambda: TeacherPolicy("oracle")):
        with pytest.raises(ConfigError, match="unknown teacher 'oracle'; rules: frontier, structure") as err:
            call()
        assert "\n" not in str(err.value)
    from realistic_indoor.agents.rl.learned import LearnedConfig

    with pytest.raises(ConfigError, match=r"LearnedConfig\.teacher must be one of"):
        LearnedConfig(teacher="oracle")


def test_teachers__go_to_a_detected_victim_first_and_never_to_a_missing_candidate():
    flat, mask = _rows({"path_cost": 0.9, "victim": 1}, {"path_cost": 0.1})
    assert teacher_choice(flat, mask, "structure") == 0
    flat, mask = _rows({"path_cost": 0.5, "in_room": 1}, {"path_cost": 0.4, "in_room": 1})
    assert teacher_choice(flat, mask, "structure") == 1  # rows 2 and 3 are zeros (cost 0) but do not exist


@pytest.mark.parametrize("env_id", ["OfficeExplore-v0", "HouseSearch-v0"])
@pytest.mark.parametrize(
    "policy", [AlwaysChoose, lambda: TeacherPolicy("frontier")], ids=["always-0", "frontier-rule"]
)
def test_learned_agent__choosing_0_drives_as_the_nearest_frontier_explorer(env_id, policy):
    kwargs = {"area_m2": 600.0} if env_id.startswith("Office") else {}
    runs = {}
    for name in ("frontier", "learned"):
        env = gym.make(env_id, **kwargs)
        options = {"model": policy()} if name == "learned" else {}
        agent = make_agent(name, env, **options)
        obs, info = env.reset(seed=5)
        agent.reset()
        actions = []
        for _ in range(300):
            action = agent.act(obs, info)
            actions.append(np.asarray(action).copy())
            obs, _, terminated, truncated, info = env.step(action)
            if terminated or truncated:
                break
        runs[name] = actions
    assert len(runs["frontier"]) == len(runs["learned"])
    assert all(np.array_equal(a, b) for a, b in zip(runs["frontier"], runs["learned"], strict=True))


def test_learned_agent__shows_the_policy_what_the_macro_environment_shows():
    """The agent's policy sees, decision by decision, the macro environment's observation."""
    model = AlwaysChoose()
    env = gym.make("OfficeExplore-v0", area_m2=600.0, max_steps=400)
    agent = make_agent("learned", env, model=model)
    assert agent.max_steps == 400  # read from the environment
    obs, info = env.reset(seed=2)
    for _ in range(400):
        obs, _, terminated, truncated, info = env.step(agent.act(obs, info))
        if terminated or truncated:
            break
    macro = gym.make("OfficeExplore-v0", area_m2=600.0, max_steps=400, action_type="frontier")
    obs, _ = macro.reset(seed=2)
    want = []
    while True:
        want.append({"candidates": obs["candidates"], "time_left": obs["time_left"]})
        obs, _, terminated, truncated, _ = macro.step(0)
        if terminated or truncated:
            break
    assert len(model.seen) == len(want) - 1 or len(model.seen) == len(want)
    for seen, expected in zip(model.seen, want, strict=False):
        assert np.array_equal(seen["obs"]["candidates"], expected["candidates"])
        assert np.array_equal(seen["obs"]["time_left"], expected["time_left"])


def test_learned_models__a_missing_or_foreign_file_is_a_one_line_error(tmp_path):
    env = gym.make("HouseExplore-v0")
    with pytest.raises(ConfigError, match="not found") as error:
        make_agent(f"learned:{tmp_path / 'missing.zip'}", env)
    assert "\n" not in str(error.value)
    text = tmp_path / "notes.zip"
    text.write_text("not a model")
    with pytest.raises(ConfigError, match="not a model archive"):
        make_agent(f"learned:{text}", env)


def test_learned_models__an_archive_of_something_else_is_a_one_line_error(tmp_path):
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    import zipfile

    env = gym.make("HouseExplore-v0")
    with zipfile.ZipFile(tmp_path / "other.zip", "w") as archive:
        archive.writestr("notes.txt", "an archive, but not of a model")
    with pytest.raises(ConfigError, match="not a MaskablePPO model") as error:
        make_agent(f"learned:{tmp_path / 'other.zip'}", env)
    assert "\n" not in str(error.value)


def test_committed_model__explores_a_house():
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    env = gym.make("HouseExplore-v0")
    agent = make_agent("learned", env)
    obs, info = env.reset(seed=1000)
    agent.reset()
    for _ in range(300):
        obs, _, terminated, truncated, info = env.step(agent.act(obs, info))
        if terminated or truncated:
            break
    assert info["coverage"] > 0.5
    assert agent.decisions > 3


def test_committed_model__came_from_the_recipe_and_its_record_is_beside_it():
    """The package's model is the realistic seed-0 model of the recipe as it is."""
    from pathlib import Path

    from realistic_indoor.agents.rl.learned import learned_preset
    from realistic_indoor.agents.rl.learned_agent import DEFAULT_MODEL, load_learned_model

    results = Path(__file__).resolve().parents[2] / "experiments" / "results"
    folder = results / "learned_pool_models"
    record = json.loads((folder / "learned_pool_realistic_seed0.json").read_text())
    assert record["config"] == learned_preset("learned").to_dict()  # the default recipe, seed 0
    assert record["config"]["teacher"] == "structure-utility-area-short"
    assert record["config"]["teacher_by_id"] == [["HouseExplore-v0", "gain"]]
    log = (folder / "learned_pool_realistic_seed0.log").read_text()
    assert f"saved runs/pool/learned_pool_realistic_seed0.zip after {record['seconds']:.0f} s" in log
    # the study's models keep no copy: the package's file is the one; the model before it lies
    # with its own track's
    assert not (folder / "learned_pool_realistic_seed0.zip").exists()
    before = json.loads((results / "learned_hr_models" / "learned_hr_realistic_seed0.json").read_text())
    assert {**before["config"], "scorer_pool": 0, "bc_balance": False} == learned_preset(
        "learned-house-rule"
    ).to_dict()
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    policy = load_learned_model(DEFAULT_MODEL).policy
    assert policy.context is True and policy.pool == record["config"]["scorer_pool"] == 16
    assert (
        load_learned_model(results / "learned_hr_models" / "learned_hr_realistic_seed0.zip").policy.pool == 0
    )


@pytest.mark.slow
def test_train_command__learned_smoke_preset_writes_a_model_and_its_log(tmp_path):
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    out = tmp_path / "m.zip"
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "realistic_indoor.cli",
            "train",
            "--preset",
            "learned-smoke",
            "--teacher",
            "utility",
            "--out",
            str(out),
            "--eval-episodes",
            "0",
            "--quiet",
        ],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    meta = json.loads(out.with_suffix(".json").read_text())
    assert meta["decisions"] >= 128 and meta["primitive_steps"] > meta["decisions"]
    assert meta["behaviour_cloning"]["decisions"] >= 64
    assert meta["config"]["teacher"] == "utility"
    assert meta["config"]["teacher_by_id"] == []  # --teacher names the one rule of every id
    for key in ("decisions_per_s", "steps_per_s", "collect_share", "machine", "seconds"):
        assert key in meta
    # the preset trains on houses alone: every decision and primitive step is theirs
    assert list(meta["by_id"]) == ["HouseExplore-v0"]
    assert meta["by_id"]["HouseExplore-v0"]["decisions"] == meta["decisions"]
    assert meta["by_id"]["HouseExplore-v0"]["primitive_steps"] == meta["primitive_steps"]
    agent = make_agent(f"learned:{out}", gym.make("HouseExplore-v0"))
    assert agent.model.action_space.n == 16
    assert agent.model.policy.context is True  # the recipe's scorer, saved and loaded with it
    assert agent.model.policy.pool == 16


@pytest.mark.slow
def test_training__the_same_seed_gives_the_same_model(tmp_path):
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    import torch

    from realistic_indoor.agents.rl.learned import learned_preset, train_learned
    from realistic_indoor.agents.rl.learned_agent import load_learned_model

    # two sub-processes, as the full recipe, each taking two ids in turn
    config = learned_preset("learned-smoke", n_envs=2, env_ids=("HouseExplore-v0", "HouseSearch-v0"))
    metas = [train_learned(config, tmp_path / f"m{i}.zip", log=lambda line: None) for i in range(2)]
    assert metas[0]["decisions"] == metas[1]["decisions"]
    assert metas[0]["primitive_steps"] == metas[1]["primitive_steps"]
    assert metas[0]["by_id"] == metas[1]["by_id"] and set(metas[0]["by_id"]) == set(config.env_ids)
    a, b = (load_learned_model(tmp_path / f"m{i}.zip").policy.state_dict() for i in range(2))
    assert a.keys() == b.keys()
    assert all(torch.equal(a[k], b[k]) for k in a)


def test_decision_context__the_offered_candidates_share_in_rooms_number_and_mean_path_cost():
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    import torch

    from realistic_indoor.agents.rl.scorer import decision_context

    flat, _ = _rows(
        {"in_room": 1.0, "path_cost": 0.2},
        {"in_room": 1.0, "path_cost": 0.4},
        {"in_room": 0.0, "path_cost": 0.6},
    )
    rows = flat.reshape(4, F).copy()
    rows[3, CANDIDATE_FEATURES.index("in_room")] = 1.0  # a row not offered (valid 0) counts for nothing
    rows[3, CANDIDATE_FEATURES.index("path_cost")] = 5.0
    got = decision_context(torch.as_tensor(rows)[None])[0].tolist()
    assert got == pytest.approx([2 / 3, 3 / 4, 0.4])  # 2 of 3 in rooms, 3 of K = 4, (0.2 + 0.4 + 0.6) / 3


def test_candidate_scorer__with_context_a_score_depends_on_the_other_candidates():
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    import torch

    from realistic_indoor.agents.rl.scorer import CandidateScorer

    flat, _ = _rows({"path_cost": 0.2, "size": 0.3}, {"path_cost": 0.5, "in_room": 0.0})
    moved = flat.reshape(4, F).copy()
    moved[1, CANDIDATE_FEATURES.index("in_room")] = 1.0  # only the second candidate changes
    batch = torch.as_tensor(
        np.stack([np.append(flat, 0.5), np.append(moved.ravel(), 0.5)]), dtype=torch.float32
    )
    for context in (False, True):
        torch.manual_seed(0)
        scorer = CandidateScorer(4, context=context)
        torch.nn.init.normal_(scorer.head.weight)  # the head starts near 0; make differences visible
        with torch.no_grad():
            first = scorer(batch)[:, 0]
        # alone, a row's score is its own; with the context, the first candidate's score sees the second's room
        assert (float(first[0]) != float(first[1])) is context


def test_candidate_scorer__the_pooled_summary_ignores_order_and_rows_not_offered():
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    import torch

    from realistic_indoor.agents.rl.scorer import CandidateScorer

    flat, _ = _rows(
        {"path_cost": 0.2, "size": 0.3, "unobserved": 0.1},
        {"path_cost": 0.5, "in_room": 1.0, "unobserved": 0.4},
        {"path_cost": 0.9, "size": 0.05},
    )
    rows = flat.reshape(4, F)
    swapped = rows[[2, 1, 0, 3]]  # the first and third candidates trade places
    hidden = rows.copy()
    hidden[3, 1:] = 0.7  # a row not offered (valid 0) with features of its own
    louder = rows.copy()
    louder[1, CANDIDATE_FEATURES.index("unobserved")] = 2.0  # only the second candidate changes
    batch = torch.as_tensor(
        np.stack([np.append(r.ravel(), 0.5) for r in (rows, swapped, hidden, louder)]), dtype=torch.float32
    )
    for pool in (0, 8):
        torch.manual_seed(0)
        scorer = CandidateScorer(4, pool=pool)
        torch.nn.init.normal_(scorer.head.weight)  # the head starts near 0; make differences visible
        with torch.no_grad():
            got = scorer(batch)
        assert got[1, [2, 1, 0]].tolist() == pytest.approx(got[0, :3].tolist(), abs=1e-6)
        assert got[2, :3].tolist() == pytest.approx(got[0, :3].tolist(), abs=1e-6)
        # alone, a row's score is its own; pooled, the first candidate's score sees the second's area
        assert (abs(float(got[3, 0] - got[0, 0])) > 1e-6) is bool(pool)


def test_cloning_weights__every_id_weighs_alike_and_the_mean_weight_is_1():
    from realistic_indoor.agents.rl.learned import _id_weights

    ids = np.array(["house", "school", "school", "school", "house", "school"])
    weights = _id_weights(ids)
    # 6 decisions, 2 ids: each id's decisions weigh 3 in all, houses 3/2 each, schools 3/4 each
    assert weights.tolist() == pytest.approx([1.5, 0.75, 0.75, 0.75, 1.5, 0.75])


def test_learned_config__a_rule_per_id_and_one_line_errors_for_bad_pairs():
    from realistic_indoor.agents.rl.learned import LearnedConfig, learned_preset
    from realistic_indoor.agents.rl.teachers import DEFAULT_TEACHER

    recipe = learned_preset("learned")
    assert recipe.rule_for("HouseExplore-v0") == "gain"
    assert recipe.rule_for("OfficeExplore-v0") == recipe.rule_for("SchoolExplore-v0") == DEFAULT_TEACHER
    one_rule = learned_preset("learned-one-rule")
    assert one_rule.rule_for("HouseExplore-v0") == DEFAULT_TEACHER and one_rule.scorer_context is False
    for pairs, says in (
        (
            (("HouseExplore-v0", "no-such-rule"),),
            "('HouseExplore-v0', 'no-such-rule') is not an (env id, rule) pair",
        ),
        ((("NoSuch-v0", "gain"),), "('NoSuch-v0', 'gain') is not an (env id, rule) pair"),
        ((("HouseExplore-v0",),), "('HouseExplore-v0',) is not"),
        ((("HouseExplore-v0", ["gain"]),), "is not an (env id, rule) pair"),
        (None, "must be (env id, rule) pairs, got None"),
        ((("HouseExplore-v0", "gain"), ("HouseExplore-v0", "frontier")), "names HouseExplore-v0 twice"),
    ):
        with pytest.raises(ConfigError) as err:
            LearnedConfig(teacher_by_id=pairs)
        assert "\n" not in str(err.value) and says in str(err.value)
    with pytest.raises(ConfigError, match="scorer_context must be True or False, got 'false'"):
        LearnedConfig(scorer_context="false")
    with pytest.raises(ConfigError, match="bc_balance must be True or False, got 1"):
        LearnedConfig(bc_balance=1)
    with pytest.raises(ConfigError, match="scorer_pool") as err:
        LearnedConfig(scorer_pool=-4)
    assert "\n" not in str(err.value)


def test_learned_models__one_saved_before_the_context_loads_without_it():
    """A model of the one-rule recipe (saved before the option) keeps its scorer of F + 1 inputs."""
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    from pathlib import Path

    from realistic_indoor.agents.rl.learned_agent import load_learned_model

    folder = Path(__file__).resolve().parents[2] / "experiments" / "results" / "learned_suas_models"
    policy = load_learned_model(folder / "learned_suas_realistic_seed0.zip").policy
    assert policy.context is False
    assert policy.action_net.body[0].in_features == len(CANDIDATE_FEATURES) + 1


@pytest.mark.slow
def test_cloning__each_id_episodes_are_chosen_by_its_own_rule(monkeypatch, tmp_path):
    pytest.importorskip("sb3_contrib", reason="the rl extra (sb3-contrib, torch) is not installed")
    from realistic_indoor.agents.rl.learned import learned_preset, train_learned

    class Counting:
        """A rule that takes the nearest candidate and counts its decisions."""

        def __init__(self) -> None:
            self.calls = 0

        def choose(self, candidates: np.ndarray, mask: np.ndarray) -> int:
            self.calls += 1
            return 0

    houses, others = Counting(), Counting()
    monkeypatch.setitem(TEACHERS, "gain", houses)
    monkeypatch.setitem(TEACHERS, "utility", others)
    config = learned_preset(
        "learned-smoke",
        env_ids=("HouseExplore-v0", "OfficeExplore-v0"),
        teacher="utility",
        teacher_by_id=(("HouseExplore-v0", "gain"),),
        bc_decisions=150,
        ppo_decisions=0,
    )
    meta = train_learned(config, tmp_path / "m.zip", log=lambda line: None)
    # one environment takes houses, then offices: every cloned decision was its id's rule's
    assert houses.calls == meta["by_id"]["HouseExplore-v0"]["decisions"] > 0
    assert others.calls == meta["by_id"]["OfficeExplore-v0"]["decisions"] > 0
    assert houses.calls + others.calls == meta["behaviour_cloning"]["decisions"] == 150
    assert set(meta["behaviour_cloning"]["agreement_by_id"]) == set(config.env_ids)
