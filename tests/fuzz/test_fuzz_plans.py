"""Property-based fuzzing of the plan readers: any malformed file is refused in one line or read
into a building that every later stage can use.

Each test starts from a valid file of ``tests/data/hostile/`` (a small house as JSON and as
floor-plan XML, a 5 x 5 World Generator map) and damages it the way hand-edited or corrupted files
are damaged: a value replaced by a hostile one, an element removed or repeated, the file cut short
or a byte flipped. Hypothesis runs derandomised, so CI sees the same examples every time.
"""

from __future__ import annotations

import json
import math
import re
import warnings
from pathlib import Path
from typing import Any

import pytest
from fuzz_settings import fuzz
from hypothesis import given
from hypothesis import strategies as st

from realistic_indoor.building import Building
from realistic_indoor.building.admit import MAX_COORDINATE_M, MAX_SPAN_M
from realistic_indoor.errors import PlanRepairWarning, RealisticIndoorError
from realistic_indoor.io import load

CORPUS = Path(__file__).resolve().parents[1] / "data" / "hostile"
FUZZ = fuzz(300)

HOSTILE_NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0, -1, 1e300, -1e300, 2**64, 10**400, 1e-320, 1e7 + 1]),
)
HOSTILE_VALUES = st.one_of(
    HOSTILE_NUMBERS,
    st.text(max_size=8),
    st.none(),
    st.booleans(),
    st.just([]),
    st.just({}),
    st.lists(st.integers(-3, 3), max_size=3),
)


def read_or_refuse(path: Path) -> Building | None:
    """Load ``path``; a refusal must be one line, and an admitted building must be usable."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", PlanRepairWarning)
            building = load(path)
    except RealisticIndoorError as e:
        assert "\n" not in str(e), str(e)
        return None
    assert_usable(building)
    return building


def assert_usable(b: Building) -> None:
    """What the gate promises of every building it lets through."""
    assert b.rooms
    xs = [x for r in b.rooms for x, _ in r.outline]
    ys = [y for r in b.rooms for _, y in r.outline]
    assert all(math.isfinite(v) and abs(v) <= MAX_COORDINATE_M for v in xs + ys)
    assert max(xs) - min(xs) <= MAX_SPAN_M and max(ys) - min(ys) <= MAX_SPAN_M
    assert len({r.id for r in b.rooms}) == len(b.rooms)
    assert all(r.polygon.is_valid and r.area > 0 for r in b.rooms)
    ids = {r.id for r in b.rooms}
    for d in b.doors:
        assert set(d.rooms) <= ids and 0 < d.width_m <= MAX_SPAN_M
        assert math.isfinite(d.x) and math.isfinite(d.y)
    b.walls  # noqa: B018 - the wall segments are computed without error
    b.graph()


def _paths(tree: Any, prefix: tuple = ()) -> list[tuple]:
    """Every path to a node of a JSON tree (keys and list indices)."""
    out = [prefix]
    if isinstance(tree, dict):
        for k, v in tree.items():
            out += _paths(v, (*prefix, k))
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            out += _paths(v, (*prefix, i))
    return out


def _damage(tree: Any, path: tuple, action: str, value: Any) -> Any:
    if not path:
        return value if action == "replace" else tree
    *head, last = path
    parent = tree
    for k in head:
        parent = parent[k]
    if action == "replace":
        parent[last] = value
    elif action == "delete":
        del parent[last]
    elif isinstance(parent, list):
        parent.append(parent[last])
    return tree


@FUZZ
@given(data=st.data())
def test_damaged_json_plans_are_refused_or_usable(tmp_path_factory, data):
    tree = json.loads((CORPUS / "house.json").read_text(encoding="utf-8"))
    for _ in range(data.draw(st.integers(1, 3), label="damages")):
        path = data.draw(st.sampled_from(_paths(tree)[1:]), label="path")
        action = data.draw(st.sampled_from(["replace", "delete", "repeat"]), label="action")
        tree = _damage(tree, path, action, data.draw(HOSTILE_VALUES, label="value"))
    file = tmp_path_factory.mktemp("json") / "plan.json"
    file.write_text(json.dumps(tree, allow_nan=True), encoding="utf-8")
    read_or_refuse(file)


_NUMBER = re.compile(rb'(?<=")-?\d+(?:\.\d+)?(?=")|(?<=>)-?\d+(?:\.\d+)?(?=<)')
HOSTILE_TOKENS = st.sampled_from(
    [b"nan", b"inf", b"-inf", b"-1", b"0", b"1e309", b"1e300", b"99999999999", b"abc", b"", b"0x10", b"1,5"]
)


@pytest.mark.parametrize("base", ["house.xml", "small.wg.xml"])
@FUZZ
@given(data=st.data())
def test_damaged_xml_plans_are_refused_or_usable(tmp_path_factory, base, data):
    text = (CORPUS / base).read_bytes()
    numbers = list(_NUMBER.finditer(text))
    for _ in range(data.draw(st.integers(1, 4), label="damages")):
        kind = data.draw(st.sampled_from(["number", "cut", "byte", "drop_line"]), label="kind")
        if kind == "number":
            m = data.draw(st.sampled_from(numbers), label="number")
            text = text[: m.start()] + data.draw(HOSTILE_TOKENS, label="token") + text[m.end() :]
            numbers = list(_NUMBER.finditer(text)) or numbers
        elif kind == "cut":
            text = text[: data.draw(st.integers(0, len(text)), label="cut")]
        elif kind == "byte":
            i = data.draw(st.integers(0, max(0, len(text) - 1)), label="at")
            text = text[:i] + bytes([data.draw(st.integers(0, 255), label="byte")]) + text[i + 1 :]
        else:
            lines = text.split(b"\n")
            del lines[data.draw(st.integers(0, len(lines) - 1), label="line")]
            text = b"\n".join(lines)
        numbers = list(_NUMBER.finditer(text)) or numbers
        if not numbers:
            break
    file = tmp_path_factory.mktemp("xml") / base
    file.write_bytes(text)
    read_or_refuse(file)


def test_the_fuzzed_bases_are_valid_plans():
    """The starting points read as buildings, so the damage is what the tests exercise."""
    for name in ("house.json", "house.xml", "small.wg.xml"):
        assert read_or_refuse(CORPUS / name) is not None, name
