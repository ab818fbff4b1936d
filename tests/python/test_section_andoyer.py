"""A section in Andoyer–Deprit variables from Python: the same columns as
the CLI's CSV, the plotted variables among them, bit for bit."""
import json

import numpy as np

import epviz
from conftest import SOURCE, assert_column_equals_csv, read_csv_columns, run_epviz

SHIPPED = SOURCE / "render_jobs" / "kovalevskaya_andoyer.section.json"


def test_the_andoyer_section_equals_the_cli_csv(tmp_path):
    section = {k: v for k, v in json.loads(SHIPPED.read_text()).items() if k not in ("png", "svg")}
    section["crossings"] = 30
    section["csv"] = "cli.csv"
    (tmp_path / "cli.section.json").write_text(json.dumps(section))
    run_epviz("section", "cli.section.json", cwd=tmp_path)
    expected = read_csv_columns(tmp_path / "cli.csv")
    result = epviz.section(str(tmp_path / "cli.section.json"))
    assert result.columns == list(expected)
    assert result.columns[-2:] == ["andoyer_l", "andoyer_L_over_G"]
    for name, fields in expected.items():
        assert_column_equals_csv(result[name], fields, name)
    # l in (−π, π], L/G a cosine.
    assert np.all(np.abs(result["andoyer_l"]) <= np.pi)
    assert np.all(np.abs(result["andoyer_L_over_G"]) <= 1.0)
