"""`--h5` of `epviz simulate` and `epviz section`, read back with h5py (an
independent reader of the format) and compared with the CSV the same
command writes: one float64 dataset per column, the job and the report as
JSON attributes, epviz's version and the SIMD path; a failed run keeps its
samples, marked failed; bad paths refused before any work; memory bounded."""
import json
import os
import pathlib
import resource
import subprocess
import sys

import h5py
import numpy as np
import pytest

from conftest import BINARY, SOURCE, assert_column_equals_csv, read_csv_columns, run_epviz


def leftovers(directory):
    return sorted(p.name for p in pathlib.Path(directory).iterdir() if ".epviz-tmp-" in p.name)


def assert_h5_equals_csv(h5_path, csv_path):
    columns = read_csv_columns(csv_path)
    with h5py.File(h5_path, "r") as f:
        assert sorted(f.keys()) == sorted(columns)
        for name, fields in columns.items():
            d = f[name]
            assert d.dtype == np.float64 and d.ndim == 1, name
            assert d.chunks is not None and d.maxshape == (None,), name
            assert_column_equals_csv(d[()], fields, name)
        return dict(f.attrs)


def test_simulate_h5_holds_the_csv_columns_and_the_report(tmp_path):
    # More rows than one chunk, and a count that is not a multiple of it.
    r = run_epviz("simulate", "--case", "kovalevskaya", "--t-end", "50", "--samples", "40000",
                  "--csv", tmp_path / "k.csv", "--report-json", tmp_path / "k.json",
                  "--h5", tmp_path / "k.h5")
    attrs = assert_h5_equals_csv(tmp_path / "k.h5", tmp_path / "k.csv")
    report = json.loads(attrs["report"])
    cli_report = json.loads((tmp_path / "k.json").read_text())
    assert report == cli_report
    assert json.loads(attrs["job"]) == {"case": "kovalevskaya", "t_end": 50, "samples": 40000}
    assert int(attrs["failed"]) == 0 and "failure" not in attrs
    version = run_epviz("--version").stdout
    assert attrs["epviz_version"] in version
    assert attrs["simd_path"] in ("scalar", "sse2", "avx2", "avx512")
    assert attrs["simd_path"] in version
    assert leftovers(tmp_path) == []
    assert r.stderr == ""


def test_simulate_h5_alone_from_a_job_file(tmp_path):
    job = tmp_path / "job.json"
    job.write_text(json.dumps({"case": "generic", "method": "rk4", "step": 0.02, "t_end": 4}))
    run_epviz("simulate", "--job", job, "--samples", "33", "--h5", tmp_path / "g.h5")
    run_epviz("simulate", "--job", job, "--samples", "33", "--csv", tmp_path / "g.csv")
    attrs = assert_h5_equals_csv(tmp_path / "g.h5", tmp_path / "g.csv")
    # The job file's fields and the option over them.
    assert json.loads(attrs["job"]) == {"case": "generic", "method": "rk4", "step": 0.02,
                                        "t_end": 4, "samples": 33}


def test_a_failed_run_keeps_its_samples_marked_failed(tmp_path):
    r = run_epviz("simulate", "--case", "euler", "--omega", "1,0,0", "--gamma", "0,0.6,0.8",
                  "--formulation", "riccati", "--no-chart-switch", "--t-end", "6",
                  "--csv", tmp_path / "f.csv", "--h5", tmp_path / "f.h5", check=False)
    assert r.returncode == 3, r.stderr
    attrs = assert_h5_equals_csv(tmp_path / "f.h5", tmp_path / "f.csv")
    assert int(attrs["failed"]) == 1
    report = json.loads(attrs["report"])
    assert report["failure_kind"] == "chart_pole"
    assert attrs["failure"] == report["failure"]["message"]
    assert f"epviz: {attrs['failure']}" in r.stderr
    with h5py.File(tmp_path / "f.h5", "r") as f:
        assert 0 < f["t"].shape[0] < 201
        assert f["t"][-1] < report["failure"]["t"]


@pytest.mark.parametrize(
    "args,names",
    [
        (["--h5", "-"], ["--h5", "standard output"]),
        (["--h5", "/dev/null"], ["--h5", "/dev/null"]),
        (["--h5", "missing-dir/k.h5"], ["--h5"]),
        (["--h5", "."], ["--h5"]),
        (["--h5", "same.out", "--csv", "same.out"], ["--h5", "--csv"]),
        (["--h5", "k.h5", "--case", "all"], ["--h5", "--case all"]),
        (["--h5", "k.h5", "--samples", "-1"], ["--samples"]),
    ],
)
def test_simulate_refuses_bad_h5_before_any_work(tmp_path, args, names):
    r = run_epviz("simulate", "--t-end", "2", *args, cwd=tmp_path, check=False)
    assert r.returncode == 2, r.stderr
    assert r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    for n in names:
        assert n in lines[0], lines[0]
    assert list(tmp_path.iterdir()) == []


def test_h5_over_an_existing_file_replaces_it_and_follows_a_link(tmp_path):
    target = tmp_path / "real.h5"
    target.write_text("old")
    (tmp_path / "link.h5").symlink_to(target)
    run_epviz("simulate", "--case", "euler", "--t-end", "1", "--samples", "3", "--h5", tmp_path / "link.h5")
    assert (tmp_path / "link.h5").is_symlink()
    with h5py.File(target, "r") as f:
        assert f["t"].shape == (4,)
    assert leftovers(tmp_path) == []


def test_section_h5_holds_the_csv_columns(tmp_path):
    section = {
        "case": "kovalevskaya",
        "level": {"energy": 2, "area": 0.5},
        "orbits": 3,
        "crossings": 40,
        "section": {"function": "gamma3", "value": 0, "direction": "upward"},
        "methods": [{"method": "dop853", "tol": 1e-10}, {"method": "rk4", "step": 0.01}],
        "csv": "s.csv",
    }
    (tmp_path / "s.section.json").write_text(json.dumps(section))
    run_epviz("section", "s.section.json", "--h5", "s.h5", cwd=tmp_path)
    columns = read_csv_columns(tmp_path / "s.csv")
    with h5py.File(tmp_path / "s.h5", "r") as f:
        methods = json.loads(f.attrs["methods"])
        assert methods == ["dop853 tol 1e-10", "rk4 step 0.01"]
        # The CSV's method column is a label; the dataset its index into "methods".
        assert [methods[int(i)] for i in f["method"][()]] == columns.pop("method")
        assert sorted(f.keys()) == sorted(["method", *columns])
        for name, fields in columns.items():
            assert_column_equals_csv(f[name][()], fields, name)
        assert json.loads(f.attrs["job"]) == section
        report = json.loads(f.attrs["report"])
        assert report["runs"] == 6 and report["crossings"] == len(columns["t"])
        assert int(f.attrs["failed"]) == 0
    assert leftovers(tmp_path) == []


def test_section_refuses_bad_h5_before_any_work(tmp_path):
    shipped = json.loads((SOURCE / "render_jobs" / "kovalevskaya.section.json").read_text())
    shipped.pop("png"), shipped.pop("svg")
    (tmp_path / "k.section.json").write_text(json.dumps(shipped))
    before = sorted(p.name for p in tmp_path.iterdir())
    for args, name in ((["--h5", "-"], "--h5"), (["--h5", shipped["csv"]], "--h5"),
                       (["--h5", "k.h5", "--shard", "0/2"], "--h5")):
        r = run_epviz("section", "k.section.json", *args, cwd=tmp_path, check=False)
        assert r.returncode == 2, r.stderr
        assert len(r.stderr.strip().splitlines()) == 1 and name in r.stderr, r.stderr
        assert sorted(p.name for p in tmp_path.iterdir()) == before


def test_memory_of_1e7_samples_to_h5_stays_under_100_mb(tmp_path):
    # A fresh Python runs the command, so that the peak RSS of its children
    # is that of this one run (resource.RUSAGE_CHILDREN keeps the largest).
    script = (
        "import resource, subprocess, sys\n"
        "r = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL)\n"
        "print(r.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", script, BINARY, "simulate", "--case", "lagrange", "--method", "rk4",
         "--step", "0.01", "--t-end", "10000", "--samples", "10000000", "--h5", tmp_path / "big.h5"],
        capture_output=True, text=True, check=True).stdout.split()
    code, peak_kb = int(out[0]), int(out[1])
    assert code == 0
    with h5py.File(tmp_path / "big.h5", "r") as f:
        assert f["t"].shape == (10000001,)
        assert f["t"][-1] == 10000.0 and f["gamma3"].shape == (10000001,)
    (tmp_path / "big.h5").unlink()  # 1 GB: not left for pytest's kept temporaries
    # 13 columns of 1e7 doubles would be 1040 MB if they were kept.
    assert peak_kb < 100 * 1024, f"peak RSS {peak_kb} kB"


SWEEP = {
    "simulation": {"case": "lagrange", "t_end": 4, "samples": 8, "method": "rk4", "step": 0.01},
    # A drift limit of 1e-14 fails rk4 (lost_motion): rows with a failure object.
    "axes": [{"field": "omega[2]", "values": [1, 3, 5]}, {"field": "max_drift", "values": [1, 1e-14]}],
}


def json_rows(path):
    rows = [json.loads(line) for line in pathlib.Path(path).read_text().splitlines() if line]
    return sorted(rows, key=lambda r: r["index"])


def assert_h5_equals_rows(h5_path, rows):
    with h5py.File(h5_path, "r") as f:
        assert f["index"][()].tolist() == [r["index"] for r in rows]
        assert f["steps"].dtype == np.float64
        assert f["steps"][()].tolist() == [r["steps"] for r in rows]
        assert f["max_relative_drift.energy"][()].tolist() == [r["max_relative_drift"]["energy"] for r in rows]
        assert f["initial.omega[2]"][()].tolist() == [r["initial"]["omega"][2] for r in rows]
        assert f["method"].asstr()[()].tolist() == [r["method"] for r in rows]
        kinds = f["failure_kind"].asstr()[()].tolist()
        assert kinds == [r["failure_kind"] or "" for r in rows]
        assert "lost_motion" in kinds and "" in kinds
        failure_t = f["failure.t"][()]
        for r, t in zip(rows, failure_t):
            assert (np.isnan(t) if r["failure"] is None else t == r["failure"]["t"])
        assert "failure" not in f  # null beside objects: no column of its own
        return dict(f.attrs)


def test_sweep_h5_holds_the_rows_in_point_order(tmp_path):
    (tmp_path / "s.sweep.json").write_text(json.dumps(SWEEP))
    run_epviz("sweep", "s.sweep.json", "--out", "rows.jsonl", "--h5", "s.h5", "-j", "2", "--quiet",
              cwd=tmp_path)
    rows = json_rows(tmp_path / "rows.jsonl")
    assert len(rows) == 6
    attrs = assert_h5_equals_rows(tmp_path / "s.h5", rows)
    assert json.loads(attrs["job"]) == SWEEP
    report = json.loads(attrs["report"])
    assert report["points"] == 6 and report["failed_points"] == sum(r["failure"] is not None for r in rows)
    assert attrs["simd_path"] in ("scalar", "sse2", "avx2", "avx512")
    assert leftovers(tmp_path) == []


def test_sweep_refuses_bad_h5_before_any_work(tmp_path):
    (tmp_path / "s.sweep.json").write_text(json.dumps(SWEEP))
    for args in (["--h5", "-"], ["--h5", "rows.jsonl"], ["--h5", "s.h5", "--shard", "0/2"]):
        r = run_epviz("sweep", "s.sweep.json", "--out", "rows.jsonl", *args, cwd=tmp_path, check=False)
        assert r.returncode == 2, r.stderr
        assert len(r.stderr.strip().splitlines()) == 1 and "--h5" in r.stderr, r.stderr
        assert sorted(p.name for p in tmp_path.iterdir()) == ["s.sweep.json"]


def test_merge_h5_writes_the_merged_sweep_and_section(tmp_path):
    (tmp_path / "s.sweep.json").write_text(json.dumps(SWEEP))
    section = {"case": "kovalevskaya", "level": {"energy": 2, "area": 0.5}, "orbits": 4,
               "crossings": 20, "csv": "k.csv"}
    (tmp_path / "k.section.json").write_text(json.dumps(section))
    shards = tmp_path / "shards"
    shards.mkdir()
    for i in range(2):
        run_epviz("sweep", tmp_path / "s.sweep.json", "--out", shards / "rows.jsonl",
                  "--shard", f"{i}/2", "--quiet", cwd=tmp_path)
        run_epviz("section", tmp_path / "k.section.json", "--out", shards / "k.csv",
                  "--shard", f"{i}/2", cwd=tmp_path)
    run_epviz("merge", shards, "--out", tmp_path / "merged", "--h5", cwd=tmp_path)
    merged = tmp_path / "merged"
    assert_h5_equals_rows(merged / "rows.h5", json_rows(merged / "rows.jsonl"))
    columns = read_csv_columns(merged / "k.csv")
    with h5py.File(merged / "k.h5", "r") as f:
        assert sorted(f.keys()) == sorted(columns)
        for name, fields in columns.items():
            assert_column_equals_csv(f[name][()], fields, name)


def test_an_interrupted_run_leaves_neither_file_nor_temporary(tmp_path):
    import signal
    import time

    p = subprocess.Popen([BINARY, "simulate", "--case", "kovalevskaya", "--tol", "1e-14", "--t-end", "1e6",
                          "--samples", "10000000", "--h5", tmp_path / "k.h5"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 20
    while not leftovers(tmp_path) and time.monotonic() < deadline:
        time.sleep(0.02)
    assert leftovers(tmp_path), "the run never wrote its temporary"
    p.send_signal(signal.SIGINT)
    assert p.wait(timeout=20) == -signal.SIGINT
    assert list(tmp_path.iterdir()) == []
