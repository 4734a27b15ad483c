import json

import pytest

from realistic_indoor.errors import PlanFormatError
from realistic_indoor.io import load, save
from realistic_indoor.io.json_format import dumps, loads


def test_json__round_trip_equal(tiny_office, tmp_path):
    path = tmp_path / "b.json"
    save(tiny_office, path)
    back = load(path)
    assert back == tiny_office
    assert dumps(back) == dumps(tiny_office)


def test_json__schema_version_checked(tiny_office):
    data = json.loads(dumps(tiny_office))
    data["version"] = 99
    with pytest.raises(PlanFormatError, match="version 99"):
        loads(json.dumps(data))


def test_json__missing_field_names_element(tiny_office):
    data = json.loads(dumps(tiny_office))
    del data["rooms"][1]["outline"]
    with pytest.raises(PlanFormatError, match=r"rooms\[1\].*outline"):
        loads(json.dumps(data), "plan.json")


def test_load__missing_file_is_a_clear_error(tmp_path):
    with pytest.raises(PlanFormatError, match="no such file"):
        load(tmp_path / "nope.json")


def test_load__unknown_extension_lists_known_ones(tmp_path):
    p = tmp_path / "plan.dxf"
    p.write_text("x")
    with pytest.raises(Exception, match=r"\.json"):
        load(p)
