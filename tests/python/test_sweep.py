"""epviz.sweep against `epviz sweep`: the rows of the command line's JSON
Lines as columns, named as `epviz sweep --h5` names its datasets."""
import json

import pytest

import epviz
from conftest import run_epviz


def test_sweep_rows_equal_the_cli_rows(tmp_path):
    # epviz.sweep against `epviz sweep`'s JSON Lines, read here with json.
    spec = {
        "simulation": {"case": "kovalevskaya", "t_end": 3, "samples": 6},
        "axes": [{"field": "method", "values": ["dop853", "rk4", "gauss4"]},
                 {"field": "omega[0]", "values": [0.1, 0.4]}],
    }
    (tmp_path / "s.sweep.json").write_text(json.dumps(spec))
    run_epviz("sweep", "s.sweep.json", "--out", "rows.jsonl", "--quiet", cwd=tmp_path)
    rows = sorted((json.loads(l) for l in (tmp_path / "rows.jsonl").read_text().splitlines()),
                  key=lambda r: r["index"])
    for result in (epviz.sweep(tmp_path / "s.sweep.json", threads=2), epviz.sweep(spec, threads=1)):
        assert result.report == {"points": 6, "failed_points": 0}
        assert result["index"].tolist() == list(range(6))
        assert result["method"] == [r["method"] for r in rows]
        assert result["initial.omega[0]"].tolist() == [r["initial"]["omega"][0] for r in rows]
        for key in ("steps", "rhs_evals", "energy"):
            assert result[key].tolist() == [r[key] for r in rows], key
        assert result["final.gamma[2]"].tolist() == [r["final"]["gamma"][2] for r in rows]
        assert result["max_relative_drift.energy"].tolist() == [r["max_relative_drift"]["energy"] for r in rows]


def test_sweep_bad_input_names_the_key():
    with pytest.raises(ValueError) as e:
        epviz.sweep({"simulation": {"case": "kovalevskaya"}, "axes": [{"field": "nope", "values": [1]}]})
    assert "\n" not in str(e.value) and "axes[0].field" in str(e.value), str(e.value)
