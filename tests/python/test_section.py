"""epviz.section against `epviz section`: the crossings' columns equal the
CSV's, from a file or from a dict; bad input is ValueError naming the key."""
import json

import numpy as np
import pytest

import epviz
from conftest import SOURCE, assert_column_equals_csv, read_csv_columns, run_epviz

SHIPPED = SOURCE / "render_jobs" / "kovalevskaya.section.json"


def cli_columns(tmp_path, section):
    # The same section without its pictures, so that the oracle needs no GL.
    section = {k: v for k, v in section.items() if k not in ("png", "svg")}
    section["csv"] = "cli.csv"
    (tmp_path / "cli.section.json").write_text(json.dumps(section))
    run_epviz("section", "cli.section.json", cwd=tmp_path)
    return read_csv_columns(tmp_path / "cli.csv")


def test_the_shipped_section_equals_the_cli_csv(tmp_path):
    expected = cli_columns(tmp_path, json.loads(SHIPPED.read_text()))
    result = epviz.section(str(SHIPPED))
    assert result.columns == list(expected)
    for name, fields in expected.items():
        assert_column_equals_csv(result[name], fields, name)
    assert len(result["gamma1"]) == result.report["crossings"] > 1000


def test_a_dict_with_several_methods(tmp_path):
    section = {
        "case": "kovalevskaya",
        "states": [{"omega": [0.3, 0.2, 0.1], "gamma": [0.6, 0, 0.8]},
                   {"omega": [0.1, 0.5, 0.0], "gamma": [0, 0.6, 0.8]}],
        "crossings": 30,
        "section": {"function": "gamma3", "value": 0.5},
        "methods": [{"method": "dop853", "tol": 1e-11}, {"method": "gauss6", "step": 0.02}],
    }
    expected = cli_columns(tmp_path, section)
    result = epviz.section(section, threads=2)
    methods = result.report["methods"]
    assert [methods[int(i)] for i in result["method"]] == expected.pop("method")
    for name, fields in expected.items():
        assert_column_equals_csv(result[name], fields, name)


@pytest.mark.parametrize(
    "change,key",
    [
        ({"orbits": 0}, "orbits"),
        ({"case": "nope"}, "case"),
        ({"crossings": "many"}, "crossings"),
        ({"colour": "red"}, "colour"),
    ],
)
def test_bad_input_is_one_line_naming_the_key(change, key):
    section = json.loads(SHIPPED.read_text())
    section.update(change)
    with pytest.raises(ValueError) as e:
        epviz.section(section)
    assert "\n" not in str(e.value) and key in str(e.value), str(e.value)
    assert str(e.value).startswith("epviz.section: ")


def test_a_missing_file_is_a_value_error_naming_it(tmp_path):
    with pytest.raises(ValueError) as e:
        epviz.section(tmp_path / "none.section.json")
    assert "none.section.json" in str(e.value)

