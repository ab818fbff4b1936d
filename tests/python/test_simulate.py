"""epviz.simulate against the command line: the same columns bit for bit as
`epviz simulate --csv`, the same report, the same refusals, and a numerical
failure that keeps the samples before it."""
import json
import pydoc
import re
import threading
import time
import _thread

import numpy as np
import pytest

import epviz
from conftest import assert_column_equals_csv, read_csv_columns, run_epviz, ticking


def cli_run(tmp_path, *args):
    csv_path, report_path = tmp_path / "run.csv", tmp_path / "run.json"
    r = run_epviz("simulate", *args, "--csv", csv_path, "--report-json", report_path, check=False)
    return r, read_csv_columns(csv_path), json.loads(report_path.read_text())


# The issue's own example, a fixed-step method, and a case without a fourth
# integral (extra_integral empty in the CSV, NaN in the arrays).
@pytest.mark.parametrize(
    "kwargs,args",
    [
        (dict(case="kovalevskaya", t_end=10, samples=100),
         ["--case", "kovalevskaya", "--t-end", "10", "--samples", "100"]),
        (dict(case="lagrange", method="rk4", step=0.01, t_end=3, samples=30),
         ["--case", "lagrange", "--method", "rk4", "--step", "0.01", "--t-end", "3", "--samples", "30"]),
        (dict(case="generic", omega=[0.1, -0.2, 0.5], formulation="spinor", tol=1e-9, t_end=2, samples=7),
         ["--case", "generic", "--omega", "0.1,-0.2,0.5", "--formulation", "spinor", "--tol", "1e-9",
          "--t-end", "2", "--samples", "7"]),
    ],
)
def test_columns_equal_the_cli_csv_bit_for_bit(tmp_path, kwargs, args):
    r, csv_columns, cli_report = cli_run(tmp_path, *args)
    assert r.returncode == 0, r.stderr
    result = epviz.simulate(**kwargs)
    assert result.columns == list(csv_columns)
    for name, fields in csv_columns.items():
        assert_column_equals_csv(result[name], fields, name)
    # The report is the command line's, but for the time it took.
    assert result.report["steps"] == cli_report["steps"] > 0
    for key in cli_report:
        if key != "cpu_seconds":
            assert result.report[key] == cli_report[key], key


def test_extra_integral_is_nan_without_a_fourth_integral():
    result = epviz.simulate(case="generic", t_end=1, samples=4)
    assert np.isnan(result["extra_integral"]).all()
    assert not np.isnan(result["energy"]).any()
    assert len(result["t"]) == 5 and result["t"][-1] == 1.0


def test_numpy_values_are_fields_too(tmp_path):
    plain = epviz.simulate(case="generic", t_end=1, samples=10, omega=[0.5, 0.1, 0.2])
    numpy = epviz.simulate(case="generic", t_end=np.float64(1), samples=np.int64(10),
                           omega=np.array([0.5, 0.1, 0.2]))
    for name in plain:
        assert np.array_equal(plain[name], numpy[name], equal_nan=True), name


# Bad input: ValueError with one line naming the key, the job reader's
# wording (the same checks as `epviz simulate --job`).
@pytest.mark.parametrize(
    "kwargs,key",
    [
        (dict(t_end=-1), "t_end"),
        (dict(tol=1.0), "tol"),
        (dict(samples=0), "samples"),
        (dict(samples=2.5), "samples"),
        (dict(method="euler-forward"), "method"),
        (dict(case="nope"), "case"),
        (dict(omega=[1, 2]), "omega"),
        (dict(inertia=[1, 1, float("nan")]), "inertia"),
        (dict(t_end="10"), "t_end"),
        (dict(tend=10), "tend"),
        (dict(case="all"), "case"),
        (dict(max_steps=0), "max_steps"),
    ],
)
def test_bad_input_is_one_line_naming_the_key(kwargs, key):
    with pytest.raises(ValueError) as e:
        epviz.simulate(**kwargs)
    message = str(e.value)
    assert "\n" not in message
    assert key in message, message


def test_the_job_file_gives_the_same_message(tmp_path):
    job = tmp_path / "bad.json"
    job.write_text('{"t_end": -1}')
    r = run_epviz("simulate", "--job", job, check=False)
    assert r.returncode == 2
    cli = r.stderr.strip().removeprefix("epviz: error: ")
    with pytest.raises(ValueError) as e:
        epviz.simulate(t_end=-1)
    # The same sentence after the name of the source ("bad.json" / "epviz.simulate").
    assert str(e.value).split(": ", 1)[1] == cli.split(": ", 1)[1]


def test_a_numerical_failure_keeps_the_samples_before_it(tmp_path):
    # A steady rotation about axis 1 carries gamma through the south pole: the
    # north Riccati chart alone cannot follow it (tests/app/simulate_output_test.cpp).
    r, csv_columns, cli_report = cli_run(
        tmp_path, "--case", "euler", "--omega", "1,0,0", "--gamma", "0,0.6,0.8",
        "--formulation", "riccati", "--no-chart-switch", "--t-end", "6")
    assert r.returncode == 3, r.stderr
    with pytest.raises(epviz.SimulationFailure) as e:
        epviz.simulate(case="euler", omega=[1, 0, 0], gamma=[0, 0.6, 0.8], formulation="riccati",
                       chart_switch=False, t_end=6)
    failure = e.value
    assert failure.kind == "chart_pole" == cli_report["failure_kind"]
    assert failure.t == cli_report["failure"]["t"]
    assert failure.method == "dop853"
    # The advice names the keyword to change.
    assert 'formulation="spinor"' in str(failure) and "chart_switch=True" in str(failure)
    assert "\n" not in str(failure)
    kept = failure.result
    assert kept.report["failure"]["t"] == failure.t
    assert 0 < len(kept["t"]) < 201
    for name, fields in csv_columns.items():
        assert_column_equals_csv(kept[name], fields, name)


def test_help_lists_every_field_of_the_command_line():
    text = pydoc.render_doc(epviz.simulate, renderer=pydoc.plaintext)
    # The oracle: the field options `epviz simulate --help` lists (--t-end is
    # the key t_end, --no-chart-switch the key chart_switch).
    help_text = run_epviz("simulate", "--help").stdout
    flags = set(re.findall(r"^\s+(--[a-z0-9-]+)", help_text, re.M))
    not_fields = {"--help", "--job", "--max-steps", "--csv", "--report-json", "--h5"}
    keys = {f[2:].removeprefix("no-").replace("-", "_") for f in flags - not_fields}
    assert len(keys) >= 15
    for key in keys:
        assert re.search(rf"\b{key}\b", text), key
        assert re.search(rf"^  {key} \(", epviz.simulate.__doc__, re.M), key
    assert "max_steps" in text


def test_the_gil_is_released_while_integrating():
    # Another thread keeps running while a run integrates in this one. A
    # call that held the GIL would stop it for the whole run.
    with ticking() as ticks:
        start = time.monotonic()
        epviz.simulate(case="kovalevskaya", tol=1e-13, t_end=1e5, samples=1000)
        end = time.monotonic()
    assert end - start > 0.3, "the run is too short to tell"
    during = [t for t in ticks if start < t < end]
    assert len(during) > 10, f"{len(during)} ticks in {end - start:.2f} s"


def test_ctrl_c_interrupts_a_long_run():
    timer = threading.Timer(0.3, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        epviz.simulate(case="kovalevskaya", tol=1e-14, t_end=1e6, samples=100000)
    assert time.monotonic() - start < 10
