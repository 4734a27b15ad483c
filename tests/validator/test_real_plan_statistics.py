"""The validator on the shared real plans (../shared/data/real_floorplans): Table 1 from the files'
own rooms and doors, the paper's connectivity facts, scale flags, label inference."""

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from realistic_indoor.building import Building, Room, SemanticLabel
from realistic_indoor.validator.compare import compare_sets
from realistic_indoor.validator.connectivity import set_connectivity
from realistic_indoor.validator.features import all_room_features
from realistic_indoor.validator.label_inference import infer_labels
from realistic_indoor.validator.plan_sets import load_plan_set
from realistic_indoor.validator.reference import paper_reference
from realistic_indoor.validator.score import realism_score
from realistic_indoor.validator.tables import label_table


@pytest.fixture(scope="session")
def real_sets(real_plans_dir):
    return {t: load_plan_set(real_plans_dir / t, t) for t in ("office", "school")}


def _file_counts(folder: Path) -> tuple[int, int, int]:
    """Spaces, spaces labelled CORRIDOR, and (space, portal) incidences, read straight from the XML."""
    spaces = corridors = incidences = 0
    for path in sorted(folder.glob("*.xml")):
        for space in ET.parse(path).getroot().findall("floor/spaces/space"):
            spaces += 1
            corridors += (space.findtext("labels/label") or "").strip().upper() == "CORRIDOR"
            incidences += len({p.findtext("linesegment") for p in space.findall("portals/portal")})
    return spaces, corridors, incidences


@pytest.mark.parametrize("kind", ["office", "school"])
def test_real_plans__table_counts_rooms_and_doorways_as_the_files_give_them(real_sets, real_plans_dir, kind):
    spaces, corridors, incidences = _file_counts(real_plans_dir / kind)
    table = label_table(real_sets[kind].buildings)
    repairs = [r["action"] for b in real_sets[kind].buildings for r in b.metadata.get("repairs", [])]
    dropped = sum(
        a.startswith("dropped the space") for a in repairs
    )  # zero-area spaces, reported by the reader
    assert dropped <= 1
    assert sum(row["count"] for row in table.values()) == spaces - dropped
    assert table[SemanticLabel.CORRIDOR]["count"] == corridors
    assert sum(row["share_pct"] for row in table.values()) == pytest.approx(100.0)
    interior_doorways = sum(sum(f.doors_to.values()) for f in all_room_features(real_sets[kind].buildings))
    exterior = sum(len(b.entrances) for b in real_sets[kind].buildings)
    assert interior_doorways + exterior == incidences


def test_real_plans__offices_show_the_paper_connectivity_facts(real_sets):
    c = set_connectivity(real_sets["office"].buildings)
    assert c.core_touching_circulation_pct >= 90  # paper: 98% of offices touch a corridor
    assert c.core_touching_corridor_pct >= 70
    assert 50 <= c.only_to_corridors_pct <= 90  # paper: about 70%
    assert c.indirect_rooms_pct <= 20  # rooms are almost never connected to each other
    assert c.dead_end_corridors_pct <= 10
    assert c.corridor_only_corridors_pct <= 10


def test_real_plans__schools_classrooms_open_onto_corridors(real_sets):
    c = set_connectivity(real_sets["school"].buildings)
    assert c.core_touching_corridor_pct >= 85
    assert c.indirect_rooms_pct <= 20


def test_real_plans__real_offices_are_closest_to_the_paper_offices(real_sets):
    offices = real_sets["office"].buildings
    scores = {r: realism_score(offices, paper_reference(r)).overall for r in ("office", "school", "house")}
    competition = realism_score(offices, paper_reference("robocup_2013_final_map")).overall
    assert min(scores, key=scores.get) == "office"
    assert competition > max(scores.values())


def test_real_plans__the_9000_m2_dentist_office_is_flagged(real_sets):
    c = compare_sets([real_sets["office"]], "office", two_sample=False)
    flagged = {Path(f.source).name for f in c.sets[0].scale_flags}
    assert any(name.startswith("dentist-office") for name in flagged)
    assert len(flagged) <= 4  # of 15: most plans look plausibly scaled


@pytest.mark.parametrize("kind", ["office", "school"])
def test_real_plans__shape_rules_find_most_corridors(real_sets, kind):
    true_pos = false_pos = false_neg = 0
    for b in real_sets[kind].buildings:
        plain = Building(
            b.building_type, tuple(Room(r.id, "medium", "unknown", r.outline) for r in b.rooms), b.doors
        )
        for r, q in zip(b.rooms, infer_labels(plain).rooms, strict=True):
            truth, guess = r.label is SemanticLabel.CORRIDOR, q.label is SemanticLabel.CORRIDOR
            true_pos += truth and guess
            false_pos += guess and not truth
            false_neg += truth and not guess
    assert true_pos / (true_pos + false_pos) >= 0.7
    assert true_pos / (true_pos + false_neg) >= 0.7
