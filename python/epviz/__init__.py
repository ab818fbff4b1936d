"""epviz from Python: the heavy top (Euler-Poisson equations) simulated,
sectioned and drawn by the same libraries as the ``epviz`` command line.

    >>> import epviz
    >>> run = epviz.simulate(case="kovalevskaya", t_end=10, samples=100)
    >>> run["energy"]           # a float64 NumPy array, the CSV column "energy"
    >>> run.report["steps"]     # the report `epviz simulate --report-json` writes

Functions:

- ``simulate(**fields)``: one run; its samples as arrays named like the
  columns of ``epviz simulate --csv``, its report as ``.report``.
- ``section(path_or_dict)``: a Poincare section's crossings as arrays named
  like the columns of ``epviz section``'s CSV.
- ``sweep(path_or_dict)``: a parameter sweep's rows as columns, named as
  ``epviz sweep --h5`` names its datasets.
- ``render_frame(job, frame=, width=, height=)``: one frame of a render job
  as a uint8 image (height, width, 4), RGBA.
- ``cloud(job)``: a render job's cloud of nearby states, every member's
  state at every frame time as 2-D arrays [member, frame], named as the
  datasets of the group "cloud" of ``epviz render --h5``.

Bad input raises ValueError with the one-line message the command line
gives for a job file; a numerical failure raises SimulationFailure, which
carries its kind, time and the samples before it. The GIL is released while
integrating and drawing; Ctrl-C ends a long run with KeyboardInterrupt.
"""

from __future__ import annotations

import collections.abc
import inspect
import json
import math
import os
import tempfile
from typing import Any, Iterator, Mapping, Optional, Union

import numpy as np

from . import _epviz

__version__: str = _epviz.version
__all__ = [
    "Result",
    "SimulationFailure",
    "cloud",
    "fields",
    "render_frame",
    "section",
    "simd_path",
    "simulate",
    "sweep",
]


class Result(collections.abc.Mapping):
    """Columns by name, each a float64 NumPy array (``result["gamma1"]``),
    in the order of the command line's CSV, and the run's report as a dict
    (``result.report``). An empty CSV field (the stereographic ``a``, ``b``
    at the south pole, ``extra_integral`` in a case without a fourth
    integral) is NaN here. A sweep's text columns ("method") are lists of
    str; a cloud's states are 2-D, one row per member."""

    def __init__(self, columns: Mapping[str, np.ndarray], report: dict):
        self._columns = dict(columns)
        self.report: dict = report

    def __getitem__(self, name: str) -> np.ndarray:
        try:
            return self._columns[name]
        except KeyError:
            raise KeyError(
                f"{name!r}: no such column (columns: {', '.join(self._columns)})"
            ) from None

    def __iter__(self) -> Iterator[str]:
        return iter(self._columns)

    def __len__(self) -> int:
        return len(self._columns)

    @property
    def columns(self) -> list:
        """The column names, in the CSV's order."""
        return list(self._columns)

    def __repr__(self) -> str:
        rows = len(next(iter(self._columns.values()))) if self._columns else 0
        return f"<epviz.Result: {rows} rows of {', '.join(self._columns)}>"


class SimulationFailure(RuntimeError):
    """A numerical failure ended the run (exit code 3 on the command line).

    Attributes: ``kind`` ("step_underflow", "lost_motion", ...), ``t`` (the
    time it was detected), ``method``, ``detail`` (the fact found), and
    ``result``: the samples before the failure and the report (whose
    "failure" says the same), or None for a rendered frame."""

    def __init__(self, message: str, failure: dict, result: Optional[Result]):
        super().__init__(message)
        self.kind: str = failure["kind"]
        self.t: float = failure["t"]
        self.method: str = failure["method"]
        self.detail: str = failure["detail"]
        self.result: Optional[Result] = result


def _plain(where: str, key: str, value: Any) -> Any:
    """A keyword's value as JSON can hold it: NumPy scalars and arrays as
    Python numbers and lists; a non-finite number is refused here (JSON has
    none), in the reader's words."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    elif isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, (list, tuple)):
        return [_plain(where, key, v) for v in value]
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    if isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f"{where}: key '{key}': expected a finite number, got {value!r}")
    return value


def _fields_json(where: str, fields: Mapping[str, Any]) -> str:
    plain = {k: _plain(where, k, v) for k, v in fields.items()}
    try:
        return json.dumps(plain)
    except TypeError as e:
        raise ValueError(f"{where}: {e}") from None


def fields() -> list:
    """The simulation fields: one dict per field (key, flag, type, default,
    help, choices, range), the table the job files, ``epviz simulate``'s
    options and ``simulate``'s keywords all come from."""
    return _epviz.field_table()


def simulate(**fields: Any) -> Result:
    # The docstring and signature are made from the field table below.
    # None is "not given", as the signature's defaults say.
    fields = {k: v for k, v in fields.items() if v is not None}
    max_steps = fields.pop("max_steps", None)
    if max_steps is not None and (isinstance(max_steps, bool) or not isinstance(max_steps, int)):
        raise ValueError(
            f"epviz.simulate: max_steps: expected an integer from 1 to 1000000000000, "
            f"got {max_steps!r}"
        )
    columns, report, failure = _epviz.simulate(_fields_json("epviz.simulate", fields), max_steps)
    result = Result(columns, json.loads(report))
    if failure is not None:
        raise SimulationFailure(failure["message"], failure, result)
    return result


def section(path_or_dict: Union[str, os.PathLike, Mapping[str, Any]], *, threads: int = 0) -> Result:
    """A Poincare section (docs/sections.md): every orbit's crossings of the
    surface, as arrays named like the columns of ``epviz section``'s CSV
    (orbit, crossing, t, omega1..3, gamma1..3, energy, area,
    gamma_norm_error, extra_integral; with several methods first "method",
    the method's index into ``.report["methods"]``).

    ``path_or_dict``: a section file, or its content as a dict (where "csv"
    may be left out: nothing is written). ``threads``: 0 for all cores.
    An orbit that loses the motion raises RuntimeError, as the command line
    exits 3."""
    if isinstance(threads, bool) or not isinstance(threads, int) or not 0 <= threads <= 4096:
        raise ValueError(f"epviz.section: threads: expected an integer from 0 to 4096, got {threads!r}")
    if isinstance(path_or_dict, Mapping):
        columns, report = _epviz.section("", _fields_json("epviz.section", path_or_dict), threads)
    else:
        columns, report = _epviz.section(os.fspath(path_or_dict), "", threads)
    return Result(columns, json.loads(report))


def sweep(path_or_dict: Union[str, os.PathLike, Mapping[str, Any]], *, threads: int = 0) -> Result:
    """A parameter sweep (docs/cluster.md): every point run, its row's values
    as columns in the order of the points, named by their path in the row as
    ``epviz sweep --h5`` names its datasets ("steps",
    "max_relative_drift.energy", "initial.omega[0]", "axes.tol"): numbers as
    float64 arrays (NaN where a row has none), text ("method",
    "failure_kind") as lists of str ("" where a row has none).
    ``.report`` holds the number of points and of failed points.

    ``path_or_dict``: a sweep file, or its content as a dict. ``threads``: 0
    for all cores. A point that fails is a row with its failure, not an error."""
    if isinstance(threads, bool) or not isinstance(threads, int) or not 0 <= threads <= 4096:
        raise ValueError(f"epviz.sweep: threads: expected an integer from 0 to 4096, got {threads!r}")
    threads = threads or (os.cpu_count() or 1)
    with tempfile.TemporaryDirectory(prefix="epviz-sweep-") as scratch:
        rows = os.path.join(scratch, "rows.jsonl")
        if isinstance(path_or_dict, Mapping):
            columns, points, failed = _epviz.sweep(
                "", _fields_json("epviz.sweep", path_or_dict), threads, rows)
        else:
            columns, points, failed = _epviz.sweep(os.fspath(path_or_dict), "", threads, rows)
    return Result(columns, {"points": points, "failed_points": failed})


def cloud(job: Union[str, os.PathLike, Mapping[str, Any]], *, threads: int = 0) -> Result:
    """The cloud of a render job (its "cloud": members and radius; see
    docs/ensembles.md), integrated as ``epviz render`` integrates it for its
    frames: DOP853 in the direct formulation at the tolerance of the job's
    first run, every member to every frame time. The same numbers as the
    group "cloud" of ``epviz render JOB --h5``, under the same names:

    - ``t``: the frame times, shape (frames,);
    - ``omega1``..``omega3``, ``gamma1``..``gamma3``: float64 arrays of shape
      (members, frames), so ``result["gamma3"][k]`` is member k's gamma3
      over time; NaN from a member's failure on;
    - ``failure_t``: when each member failed (NaN for one that reached the
      end); ``failure_kind``: how ("step_underflow", ...; "" for none), a
      list of str.

    ``.report`` holds what the group's attributes hold: members, radius,
    frames, run ("run0": the run the cloud is launched with), method,
    formulation, tol and failed_members.

    ``job``: a job file, a shipped job's name ("cloud_generic"), or a job as
    a dict. ``threads``: 0 for all cores (the numbers do not depend on it).
    The GIL is released while integrating; Ctrl-C ends it with
    KeyboardInterrupt between chunks of 1,024 members. A job without a
    "cloud" raises ValueError."""
    if isinstance(threads, bool) or not isinstance(threads, int) or not 0 <= threads <= 4096:
        raise ValueError(f"epviz.cloud: threads: expected an integer from 0 to 4096, got {threads!r}")
    threads = threads or (os.cpu_count() or 1)
    if isinstance(job, Mapping):
        columns, report = _epviz.cloud("", _fields_json("epviz.cloud", job), threads)
    else:
        columns, report = _epviz.cloud(os.fspath(job), "", threads)
    return Result(columns, json.loads(report))


def render_frame(
    job: Union[str, os.PathLike, Mapping[str, Any]],
    frame: int = 0,
    width: Optional[int] = None,
    height: Optional[int] = None,
    gl: Optional[str] = None,
) -> np.ndarray:
    """Frame ``frame`` (from 0) of a render job, drawn as ``epviz render``
    draws it: a uint8 array of shape (height, width, 4), RGBA, row 0 at the
    top (``matplotlib.pyplot.imshow`` shows it as it is).

    ``job``: a job file, a shipped job's name ("kovalevskaya"), or a job as a
    dict. ``width``, ``height``: the frame's size (default the job's).
    ``gl``: "auto", "egl" or "osmesa", as ``--gl`` (default: $EPVIZ_GL, else
    auto). A numerical failure before the frame raises SimulationFailure."""
    if not _epviz.has_render:
        raise RuntimeError("epviz.render_frame: this epviz was built without the renderer")
    for key, value in (("frame", frame), ("width", width), ("height", height)):
        if value is not None and (isinstance(value, bool) or not isinstance(value, (int, np.integer))):
            raise ValueError(f"epviz.render_frame: {key}: expected an integer, got {value!r}")
    if isinstance(job, Mapping):
        path, text = "", _fields_json("epviz.render_frame", job)
    else:
        path, text = os.fspath(job), ""
    image = _epviz.render_frame(
        path, text, int(frame), int(width or 0), int(height or 0), gl or ""
    )
    if isinstance(image, dict):
        raise SimulationFailure(image["message"], image, None)
    return image


def simd_path() -> str:
    """The SIMD path the batch integrators take in this process, and why
    ("avx2 (widest of this CPU)", "sse2 (EPVIZ_SIMD)")."""
    return _epviz.simd_path()


_TYPES = {"str": str, "vec3": "tuple[float, float, float]", "float": float, "int": int, "bool": bool}


def _simulate_doc() -> str:
    lines = [
        "One simulation, given by the job's field names: the keys of a job's",
        '"simulation" object (`epviz render --help-job`), the options of',
        "`epviz simulate` (`--t-end` is t_end).",
        "",
        "Returns a Result: result[name] is the CSV column `name` of",
        "`epviz simulate --csv` as a float64 NumPy array (t, omega1..3, gamma1..3,",
        "a, b, energy, area, gamma_norm_error, extra_integral), bit for bit the",
        "numbers the CSV holds; result.report is the report of --report-json.",
        "",
        "Raises ValueError for bad input (the job reader's one-line message) and",
        "SimulationFailure for a numerical failure (with .kind, .t and .result,",
        "the samples before it).",
        "",
        "Fields (all optional; a case's preset fills what is not given):",
    ]
    for f in _epviz.field_table():
        kind = {"vec3": "three numbers", "float": "number", "int": "integer", "bool": "bool",
                "str": "str"}[f["type"]]
        text = f"  {f['key']} ({kind}): {f['help']}"
        if f["choices"]:
            text += f"; one of {f['choices']}"
        if f["range"]:
            text += f" ({f['range']})"
        if f["default"]:
            text += f" (default {f['default']})"
        lines.append(text)
    lines.append("  max_steps (integer): adaptive methods: end the run as failed after this")
    lines.append("    many steps (default 1e8), as --max-steps")
    return "\n".join(lines)


def _simulate_signature() -> inspect.Signature:
    params = []
    for f in _epviz.field_table():
        annotation = _TYPES[f["type"]]
        params.append(
            inspect.Parameter(
                f["key"], inspect.Parameter.KEYWORD_ONLY, default=None,
                annotation=f"Optional[{getattr(annotation, '__name__', annotation)}]",
            )
        )
    params.append(
        inspect.Parameter("max_steps", inspect.Parameter.KEYWORD_ONLY, default=None,
                          annotation="Optional[int]")
    )
    return inspect.Signature(params, return_annotation="Result")


simulate.__doc__ = _simulate_doc()
simulate.__signature__ = _simulate_signature()  # type: ignore[attr-defined]
