"""Shared helpers of the Python tests (tests/CMakeLists.txt runs each file
as its own CTest test, with PYTHONPATH=build/python and EPVIZ_BINARY, the
built command line, which is the oracle the module is compared with)."""
import contextlib
import csv
import math
import os
import pathlib
import subprocess
import threading
import time

import numpy as np
import pytest

SOURCE = pathlib.Path(os.environ.get("EPVIZ_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = os.path.abspath(os.environ.get("EPVIZ_BINARY", str(SOURCE / "build" / "epviz")))


def run_epviz(*args, cwd=None, check=True):
    """The command line with `args`; its CompletedProcess (text)."""
    r = subprocess.run([BINARY, *map(str, args)], cwd=cwd, capture_output=True, text=True)
    if check and r.returncode != 0:
        raise AssertionError(f"epviz {' '.join(map(str, args))} exited {r.returncode}: {r.stderr}")
    return r


def read_csv_columns(path):
    """{column: list of str} of a CSV file, read as text: the fields exactly as written."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: [row[i] for row in body] for i, name in enumerate(header)}


def assert_column_equals_csv(array, fields, name=""):
    """`array` holds the numbers of the CSV `fields` bit for bit: float() of
    the text (which reads back the very double that was written, %.17g or
    shortest form), NaN where the field is empty."""
    array = np.asarray(array)
    assert array.dtype == np.float64, name
    assert array.shape == (len(fields),), f"{name}: {array.shape} vs {len(fields)} rows"
    expected = np.array([float(x) if x != "" else math.nan for x in fields], dtype=np.float64)
    empty = np.array([x == "" for x in fields], dtype=bool)
    assert np.array_equal(np.isnan(array), empty), f"{name}: NaN where the CSV is not empty, or not where it is"
    same = expected[~empty].view(np.uint64) == array[~empty].view(np.uint64)
    assert same.all(), f"{name}: differs at rows {np.flatnonzero(~same)[:5]}"


@pytest.fixture
def source():
    return SOURCE


@contextlib.contextmanager
def ticking():
    """Another thread records a tick every 5 ms while the body runs, and the
    list of tick times is yielded: a call that held the GIL would stop it for
    as long as it runs."""
    done = threading.Event()
    ticks = []

    def count():
        while True:
            ticks.append(time.monotonic())
            if done.wait(0.005):
                break

    counter = threading.Thread(target=count)
    counter.start()
    try:
        yield ticks
    finally:
        done.set()
        counter.join()
