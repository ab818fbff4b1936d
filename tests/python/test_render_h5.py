"""`epviz render JOB --h5`, read back with h5py: each run of the job a group
whose columns are those `epviz simulate --csv` writes for the same run's
settings (an independent path: the settings are taken from the job and
render's own report), the cloud against epviz.cloud and against `epviz
simulate` of one member's initial state; attributes as `simulate --h5` has
them; a failed run kept and marked; bad --h5 refused before any work."""
import json
import pathlib
import threading
import time
import _thread

import h5py
import numpy as np
import pytest

import epviz
from conftest import SOURCE, assert_column_equals_csv, read_csv_columns, run_epviz, ticking

RUNS_JOB = {
    "title": "three runs to HDF5",
    "simulation": {"case": "generic", "t_end": 6},
    "runs": [
        {"label": "reference", "method": "dop853", "tol": "auto"},
        {"label": "coarse", "method": "rk4", "step": 0.05, "formulation": "spinor"},
        {"label": "chart", "method": "dop853", "tol": 1e-9, "formulation": "riccati",
         "omega": [0.3, -0.2, 0.9]},
    ],
    "width": 160, "height": 96, "fps": 10, "duration": 2,
    "output": {"dir": "frames", "format": "png"},
}

# 1,100 members: two chunks of the integration (1,024 each).
CLOUD_JOB = {
    "simulation": {"case": "generic", "t_end": 12, "method": "dop853", "tol": 1e-10,
                   "omega": [1.0, 0.8, 0.6],
                   "gamma": [0.7198463103929541, 0.6040227735550536, 0.3420201433256688]},
    "cloud": {"members": 1100, "radius": 0.05},
    "width": 160, "height": 96, "fps": 10, "duration": 2,
    "output": {"dir": "frames", "format": "png"},
}

SAMPLE_COLUMNS = ["t", "omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "a", "b",
                  "energy", "area", "gamma_norm_error", "extra_integral"]


def leftovers(directory):
    return sorted(p.name for p in pathlib.Path(directory).iterdir() if ".epviz-tmp-" in p.name)


def write_job(tmp_path, job, name="job.json"):
    path = tmp_path / name
    path.write_text(json.dumps(job))
    return path


def render(tmp_path, job_path, *args, check=True):
    return run_epviz("render", job_path, "--frames", "0", "--quiet", *args, cwd=tmp_path, check=check)


def flags(fields):
    """`epviz simulate` options for job fields, by the field table's flags."""
    flag = {f["key"]: f["flag"] for f in epviz.fields()}
    args = []
    for key, value in fields.items():
        if isinstance(value, bool):
            args.append(f"{flag[key]}" if value else f"--no-{flag[key][2:]}")
        elif isinstance(value, list):
            args += [flag[key], ",".join(repr(float(v)) for v in value)]
        else:
            args += [flag[key], repr(value) if isinstance(value, float) else str(value)]
    return args


def test_each_run_is_simulate_of_its_settings(tmp_path):
    job = write_job(tmp_path, RUNS_JOB)
    render(tmp_path, job, "--h5", "r.h5", "--report-json", "r.json")
    report = json.loads((tmp_path / "r.json").read_text())
    with h5py.File(tmp_path / "r.h5", "r") as f:
        assert sorted(k for k in f.keys()) == ["run0", "run1", "run2"]
        for i, run in enumerate(RUNS_JOB["runs"]):
            group, drawn = f[f"run{i}"], report["runs"][i]
            assert sorted(group.keys()) == sorted(SAMPLE_COLUMNS)
            assert group.attrs["label"] == run["label"] == drawn["label"]
            assert group.attrs["method"] == run["method"] == drawn["method"]
            assert group.attrs["formulation"] == drawn["formulation"]
            assert int(group.attrs["failed"]) == 0 and "failure" not in group.attrs
            t = group["t"]
            assert t.chunks is not None and t.maxshape == (None,)
            assert t[-1] == RUNS_JOB["simulation"]["t_end"] and t[0] == 0
            # The run's settings: the job's fields under its own, the method,
            # formulation and (resolved) tolerance render reports it drew with.
            fields = {**RUNS_JOB["simulation"], **run}
            fields.pop("label")
            fields["formulation"] = drawn["formulation"]
            if drawn["tol"] is not None:
                fields["tol"] = drawn["tol"]
            fields["samples"] = t.shape[0] - 1
            csv_path, json_path = tmp_path / f"run{i}.csv", tmp_path / f"run{i}.json"
            run_epviz("simulate", *flags(fields), "--csv", csv_path, "--report-json", json_path)
            columns = read_csv_columns(csv_path)
            assert list(columns) == SAMPLE_COLUMNS
            for name, values in columns.items():
                assert_column_equals_csv(group[name][()], values, f"run{i}/{name}")
            # The group's report is simulate's of the same run, but for the time it took.
            ours, cli = json.loads(group.attrs["report"]), json.loads(json_path.read_text())
            for key in cli:
                if key != "cpu_seconds":
                    assert ours[key] == cli[key], (i, key)
    assert leftovers(tmp_path) == []


def test_attributes_follow_simulate_h5(tmp_path):
    job = write_job(tmp_path, RUNS_JOB)
    r = render(tmp_path, job, "--h5", "r.h5", "--report-json", "r.json")
    with h5py.File(tmp_path / "r.h5", "r") as f:
        attrs = dict(f.attrs)
    assert json.loads(attrs["report"]) == json.loads((tmp_path / "r.json").read_text())
    drawn = json.loads(attrs["job"])
    # The job as drawn: its keys in their canonical form (an absent tolerance is "auto").
    assert drawn["simulation"] == {**RUNS_JOB["simulation"], "tol": "auto"}
    assert [run["label"] for run in drawn["runs"]] == ["reference", "coarse", "chart"]
    assert drawn["width"] == 160 and drawn["output"]["dir"] == "frames"
    assert int(attrs["failed"]) == 0 and "failure" not in attrs
    assert int(attrs["runs"]) == 3
    assert attrs["epviz_version"] in run_epviz("--version").stdout
    assert attrs["simd_path"] in ("scalar", "sse2", "avx2", "avx512")
    assert "r.h5: 3 runs (0 failed)" in r.stdout


def test_a_run_that_fails_keeps_its_samples_marked_failed(tmp_path):
    # The second run's Riccati chart reaches its pole (chart switching off).
    job = write_job(tmp_path, {
        "simulation": {"case": "euler", "t_end": 6, "omega": [1, 0, 0], "gamma": [0, 0.6, 0.8]},
        "runs": [{"label": "spinor", "formulation": "spinor"},
                 {"label": "pole", "formulation": "riccati", "chart_switch": False}],
        "width": 160, "height": 96, "fps": 10, "duration": 2,
        "output": {"dir": "frames", "format": "png"},
    })
    # --frames 0 stops before the failure: the file's run fails the render all the same.
    r = render(tmp_path, job, "--h5", "f.h5", check=False)
    assert r.returncode == 3, r.stderr
    with h5py.File(tmp_path / "f.h5", "r") as f:
        assert int(f.attrs["failed"]) == 1
        pole = f["run1"]
        assert int(pole.attrs["failed"]) == 1
        failure = json.loads(pole.attrs["report"])["failure"]
        assert json.loads(pole.attrs["report"])["failure_kind"] == "chart_pole"
        assert 0 < pole["t"].shape[0] < f["run0"]["t"].shape[0]
        assert pole["t"][-1] < failure["t"]
        assert f.attrs["failure"] == pole.attrs["failure"]
        assert r.stderr.count(pole.attrs["failure"]) == 1, r.stderr
        # The other run goes on to the end.
        assert int(f["run0"].attrs["failed"]) == 0 and f["run0"]["t"][-1] == 6
    assert leftovers(tmp_path) == []


def test_cloud_equals_epviz_cloud(tmp_path):
    job = write_job(tmp_path, CLOUD_JOB)
    r = render(tmp_path, job, "--h5", "c.h5")
    assert "a cloud of 1100 members (0 failed)" in r.stdout
    cloud = epviz.cloud(job)
    assert cloud.columns == ["t", "omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3",
                             "failure_t", "failure_kind"]
    with h5py.File(tmp_path / "c.h5", "r") as f:
        g = f["cloud"]
        assert sorted(g.keys()) == sorted(cloud.columns)
        frames = g["t"].shape[0]
        assert frames == cloud.report["frames"] > 2
        for name in cloud.columns[1:7]:
            assert g[name].shape == (1100, frames) and g[name].dtype == np.float64
            assert np.array_equal(g[name][()], cloud[name]), name
            assert np.isfinite(cloud[name]).all(), name
        assert np.array_equal(g["t"][()], cloud["t"])
        assert np.isnan(g["failure_t"][()]).all() and np.isnan(cloud["failure_t"]).all()
        assert g["failure_kind"].asstr()[()].tolist() == cloud["failure_kind"] == [""] * 1100
        assert dict(g.attrs) == cloud.report
        assert cloud.report["failed_members"] == 0 and cloud.report["tol"] == 1e-10
    # The same numbers on any number of threads, from a dict as from the file.
    one = epviz.cloud(CLOUD_JOB, threads=1)
    for name in cloud.columns[:7]:
        assert np.array_equal(one[name], cloud[name]), name


def test_a_member_is_simulate_of_its_initial_state(tmp_path):
    cloud = epviz.cloud(write_job(tmp_path, CLOUD_JOB))
    frames = len(cloud["t"])
    t_end = CLOUD_JOB["simulation"]["t_end"]
    for k in (0, 1023, 1024, 1099):
        omega = [cloud[f"omega{i}"][k, 0] for i in (1, 2, 3)]
        gamma = [cloud[f"gamma{i}"][k, 0] for i in (1, 2, 3)]
        csv_path = tmp_path / f"m{k}.csv"
        run_epviz("simulate", "--case", "generic", "--method", "dop853", "--formulation", "direct",
                  "--tol", "1e-10", "--omega", ",".join(map(repr, omega)),
                  "--gamma", ",".join(map(repr, gamma)), "--t-end", str(t_end),
                  "--samples", str(frames - 1), "--csv", csv_path)
        columns = read_csv_columns(csv_path)
        t = np.array([float(x) for x in columns["t"]])
        # The frame times, t_end k / (frames - 1), and simulate's, k t_end / samples,
        # are the same instants to the last bit or two.
        assert np.allclose(t, cloud["t"], rtol=0, atol=4e-15 * t_end)
        same_time = t == cloud["t"]
        assert same_time.sum() > frames // 2
        for name in ("omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3"):
            x = np.array([float(v) for v in columns[name]])
            # Bit for bit where the times agree, the scalar DOP853 on the member alone.
            assert np.array_equal(x[same_time], cloud[name][k][same_time]), (k, name)
            assert np.allclose(x, cloud[name][k], rtol=0, atol=1e-12), (k, name)


def test_a_job_without_a_cloud_is_a_value_error(tmp_path):
    with pytest.raises(ValueError) as e:
        epviz.cloud("kovalevskaya")
    assert "\n" not in str(e.value) and "cloud" in str(e.value)
    for threads in (-1, 1.5, True, 5000):
        with pytest.raises(ValueError, match="threads"):
            epviz.cloud(CLOUD_JOB, threads=threads)
    with pytest.raises(ValueError, match="members"):
        epviz.cloud({**CLOUD_JOB, "cloud": {"members": 0}})


def test_the_gil_is_released_and_ctrl_c_interrupts_a_cloud():
    big = {**CLOUD_JOB, "cloud": {"members": 100000, "radius": 0.05},
           "simulation": {**CLOUD_JOB["simulation"], "t_end": 400}, "duration": 0.2}
    timer = threading.Timer(1.0, _thread.interrupt_main)
    with ticking() as ticks:
        start = time.monotonic()
        timer.start()
        try:
            with pytest.raises(KeyboardInterrupt):
                epviz.cloud(big)
            end = time.monotonic()
        finally:
            timer.cancel()
    assert end - start < 15
    during = [t for t in ticks if start < t < end]
    assert len(during) > 20, f"{len(during)} ticks in {end - start:.2f} s"


@pytest.mark.parametrize(
    "args,names",
    [
        (["--h5", "-"], ["--h5", "standard output"]),
        (["--h5", "/dev/null"], ["--h5", "/dev/null"]),
        (["--h5", "missing-dir/r.h5"], ["--h5"]),
        (["--h5", "."], ["--h5"]),
        (["--h5", "job.json"], ["--h5", "job"]),
        (["--h5", "same.out", "--report-json", "same.out"], ["--h5", "--report-json"]),
        (["--h5", "r.h5", "--shard", "0/2"], ["--h5", "shard"]),
    ],
)
def test_render_refuses_bad_h5_before_any_work(tmp_path, args, names):
    write_job(tmp_path, CLOUD_JOB)
    r = run_epviz("render", "job.json", *args, cwd=tmp_path, check=False)
    assert r.returncode == 2, r.stderr
    assert r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1, r.stderr
    for n in names:
        assert n in lines[0], lines[0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["job.json"]


@pytest.mark.parametrize("job", ["gallery.json", "bench_figures_quick.json"])
def test_a_gallery_or_bench_job_refuses_h5(tmp_path, job):
    r = run_epviz("render", SOURCE / "render_jobs" / job, "--out", "out", "--h5", "r.h5",
                  cwd=tmp_path, check=False)
    assert r.returncode == 2, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and "--h5" in r.stderr, r.stderr
    assert list(tmp_path.iterdir()) == []
