// The compiled half of the Python module `epviz` (python/epviz/__init__.py is
// the other): the same libraries as the command line, called with the job's
// field names. Input comes as JSON text (the Python layer dumps its keyword
// arguments), so that it is read and checked by the same readers as a job
// file; io::BadInput becomes ValueError with the reader's one-line message.
// The GIL is released while integrating and drawing; a pending signal
// (Ctrl-C) is looked at every few thousand samples and ends the run with
// KeyboardInterrupt.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "h5/json_rows.hpp"
#include "io/bad_input.hpp"
#include "io/json_reader.hpp"
#include "job/fields.hpp"
#include "job/job_file.hpp"
#include "job/job_plan.hpp"
#include "job/schema.hpp"
#include "job/shipped_jobs.hpp"
#include "numerics/failure.hpp"
#include "numerics/simd_path.hpp"
#include "scene/cloud_run.hpp"
#include "section/section_csv.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"
#include "sim/drift.hpp"
#include "sim/failure_advice.hpp"
#include "sim/methods.hpp"
#include "sim/run_options.hpp"
#include "sim/simulate.hpp"
#include "sweep/rows_file.hpp"
#include "sweep/simulate_runs.hpp"
#include "sweep/simulation_output.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_spec.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "paint/frame_drawer.hpp"
#include "paint/frame_painter.hpp"
#include "render/gl_choice.hpp"
#endif

namespace py = pybind11;

namespace epviz::python {
namespace {

// A vector's storage handed to NumPy without a copy: the array owns it.
py::array_t<double> to_array(std::vector<double>&& values) {
  auto* owned = new std::vector<double>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({owned->size()}, {sizeof(double)}, owned->data(), owner);
}

// values (rows x columns, row-major) as a 2-D array, without a copy.
py::array_t<double> to_matrix(std::vector<double>&& values, std::size_t rows, std::size_t columns) {
  auto* owned = new std::vector<double>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({rows, columns}, {columns * sizeof(double), sizeof(double)},
                             owned->data(), owner);
}

// Thrown from inside a run (the GIL released) when Python has a signal
// pending; the Python error (KeyboardInterrupt) is set and raised once the
// GIL is back.
struct Interrupted {};

class SignalCheck {
 public:
  void operator()() {
    if (++calls_ % 4096 == 0) now();
  }
  // Looks at once (between chunks of work that take a while each).
  void now() {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw Interrupted{};
  }

 private:
  long calls_ = 0;
};

nlohmann::json object_from(const std::string& json_text, const std::string& name) {
  const nlohmann::json doc = io::parse_json_text(json_text, name);
  if (!doc.is_object()) throw io::BadInput(name + ": expected an object of fields");
  return doc;
}

py::dict failure_dict(const numerics::Failure& f) {
  py::dict d;
  d["kind"] = std::string(numerics::name(f.kind));
  d["t"] = f.t;
  d["method"] = f.method;
  d["detail"] = f.detail;
  d["message"] = sim::failure_line(f, sim::SettingsIn::python);
  return d;
}

// {name: array}, report (JSON text), failure (dict or None).
py::tuple simulate(const std::string& fields_json, std::optional<long> max_steps) {
  const std::string name = "epviz.simulate";
  const nlohmann::json doc = object_from(fields_json, name);
  io::ObjectReader reader(doc, name);
  const job::SimulationFields fields = job::read_simulation_fields(reader);
  reader.finish();
  if (sweep::runs_every_case(fields))
    throw io::BadInput(name + ": key 'case': 'all' runs every preset; simulate one case a call");
  if (max_steps && (*max_steps < 1 || *max_steps > 1'000'000'000'000))
    throw io::BadInput(name + ": max_steps: expected an integer from 1 to 1000000000000, got " +
                       std::to_string(*max_steps));
  const sim::RunSpec spec = sweep::simulate_runs(fields, max_steps).front();

  const auto& names = sweep::sample_column_names();
  std::array<std::vector<double>, sweep::kSampleColumns> columns;
  for (auto& c : columns) c.reserve(std::size_t(spec.samples) + 1);
  sim::RunDriftMonitor drifts(spec);
  const sweep::SampleColumns values(spec);
  sim::RunResult result;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    SignalCheck check;
    try {
      result = sim::simulate(
          spec,
          [&](const sim::Sample& s) {
            drifts.output(s);
            const auto row = values.row(s);
            for (std::size_t i = 0; i < columns.size(); ++i) columns[i].push_back(row.values[i]);
            check();
          },
          [&](const sim::Sample& s) {
            drifts.step(s);
            check();
          });
    } catch (const Interrupted&) {
      interrupted = true;
    }
  }
  if (interrupted) throw py::error_already_set();
  py::dict arrays;
  for (std::size_t i = 0; i < columns.size(); ++i)
    arrays[py::str(names[i])] = to_array(std::move(columns[i]));
  const std::string report = sweep::simulate_report(spec, result, drifts.drifts()).dump();
  py::object failure = py::none();
  if (result.failure) failure = failure_dict(*result.failure);
  return py::make_tuple(arrays, report, failure);
}

// {name: array} of the crossings, the report (JSON text).
py::tuple section(const std::string& path, const std::string& object_json, int threads) {
  section::SectionJob job =
      path.empty() ? section::read_section_object(object_from(object_json, "epviz.section"),
                                                  "epviz.section", false)
                   : section::read_section_job(path);
  const auto starts = section::section_starts(job);
  std::vector<section::OrbitResult> results;
  {
    py::gil_scoped_release release;
    results = section::run_section(job, starts, section::thread_count(threads));
  }
  if (const std::string lost = section::lost_orbits_line(job, results); !lost.empty())
    throw std::runtime_error(job.file + ": " + lost);
  const auto names = section::crossing_columns(job);
  std::vector<std::vector<double>> columns(names.size());
  section::for_each_crossing_row(job, results, [&](std::span<const double> row) {
    for (std::size_t i = 0; i < row.size(); ++i) columns[i].push_back(row[i]);
  });
  const std::size_t crossings = columns.front().size();
  py::dict arrays;
  for (std::size_t i = 0; i < names.size(); ++i)
    arrays[py::str(names[i])] = to_array(std::move(columns[i]));
  nlohmann::json methods = nlohmann::json::array();
  for (const auto& m : job.methods) methods.push_back(section::method_label(m));
  const nlohmann::json report{{"runs", results.size()},
                              {"crossings", crossings},
                              {"methods", methods},
                              {"summary", section::summary(job, starts.size(), results)}};
  return py::make_tuple(arrays, report.dump());
}

// A sweep's rows, run into `rows_file` (a scratch file of the Python layer)
// and read back in the order of their points: {name: array} by
// h5::json_columns (the names `epviz sweep --h5` gives its datasets; text
// columns as lists of str), and the number of failed points.
py::tuple sweep(const std::string& path, const std::string& object_json, int threads,
                const std::string& rows_file) {
  const sweep::SweepSpec spec =
      path.empty() ? sweep::read_sweep(object_from(object_json, "epviz.sweep"), "epviz.sweep")
                   : sweep::read_sweep_file(path);
  const long total = spec.point_count();
  const auto pending = sweep::pending_points(spec, {0, total}, {});
  sweep::SweepTotals totals;
  {
    py::gil_scoped_release release;
    sweep::RowAppender rows(rows_file);
    totals = sweep::run_points(spec, pending, std::max(1, threads), rows);
    rows.flush();
  }
  std::vector<nlohmann::json> rows;
  std::ifstream in(rows_file);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) rows.push_back(io::parse_json_text(line, rows_file));
  std::stable_sort(rows.begin(), rows.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return a.value("index", 0L) < b.value("index", 0L);
  });
  py::dict columns;
  for (auto& c : h5::json_columns(rows)) {
    if (c.text)
      columns[py::str(c.name)] = py::cast(c.texts);
    else
      columns[py::str(c.name)] = to_array(std::move(c.numbers));
  }
  return py::make_tuple(columns, total, totals.failures);
}

// A single render job: a file, a shipped job's name, or a job's content
// (JSON text) read as a file would be, named `name` in messages.
job::RenderJob render_job(const std::string& path, const std::string& object_json,
                          const std::string& name) {
  if (path.empty()) {
    const auto doc = job::read_job(object_from(object_json, name), name);
    return {name, doc.simulation, doc.runs, doc.scene, doc.output};
  }
  auto loaded = job::load_job_file(job::job_file_named(path, job::shipped_jobs_dir()));
  if (!loaded.single)
    throw io::BadInput(path + ": " + name +
                       " takes a single render job, not a gallery or bench-figures job");
  return std::move(*loaded.single);
}

// A render job's cloud, integrated as `epviz render` integrates it
// (scene::integrate_cloud), as the datasets of the group "cloud" of `epviz
// render --h5`: {name: array} and what its attributes say (JSON text).
py::tuple cloud(const std::string& path, const std::string& object_json, int threads) {
  const std::string name = "epviz.cloud";
  const job::RenderJob job = render_job(path, object_json, name);
  const auto& settings = job.scene.cloud;
  if (!settings.enabled())
    throw io::BadInput((path.empty() ? name : path) +
                       ": the job has no \"cloud\" (give it {\"members\": N, \"radius\": r})");
  const scene::ScenePlan plan = job::plan_job(job);
  std::vector<double> times = scene::cloud_times(plan);
  const auto members = std::size_t(settings.members), frames = times.size();
  std::array<std::vector<double>, 6> state;
  for (auto& c : state) c.resize(members * frames);
  std::vector<double> failure_t(members, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::string> failure_kind(members);
  long failed = 0;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    SignalCheck check;
    try {
      scene::integrate_cloud(
          plan.run, settings, times, threads,
          [&](std::size_t first, const std::vector<sim::DirectBatchResult>& results) {
            const auto rows = scene::cloud_rows(first, results, frames);
            for (std::size_t c = 0; c < state.size(); ++c)
              std::copy(rows.state[c].begin(), rows.state[c].end(),
                        state[c].begin() + std::ptrdiff_t(first * frames));
            std::copy(rows.failure_t.begin(), rows.failure_t.end(),
                      failure_t.begin() + std::ptrdiff_t(first));
            std::copy(rows.failure_kind.begin(), rows.failure_kind.end(),
                      failure_kind.begin() + std::ptrdiff_t(first));
            failed += rows.failed;
            check.now();
          });
    } catch (const Interrupted&) {
      interrupted = true;
    }
  }
  if (interrupted) throw py::error_already_set();
  const auto& names = sweep::sample_column_names();  // t, omega1..3, gamma1..3, ...
  py::dict arrays;
  arrays[py::str(names[0])] = to_array(std::move(times));
  for (std::size_t c = 0; c < state.size(); ++c)
    arrays[py::str(names[1 + c])] = to_matrix(std::move(state[c]), members, frames);
  arrays["failure_t"] = to_array(std::move(failure_t));
  arrays["failure_kind"] = py::cast(failure_kind);
  const nlohmann::json report{{"members", settings.members},
                              {"radius", settings.radius},
                              {"frames", plan.frames},
                              {"run", "run0"},
                              {"method", std::string(sim::name(sim::Method::dop853))},
                              {"formulation", std::string(sim::name(sim::Formulation::direct))},
                              {"tol", sim::adaptive_tol(plan.run)},
                              {"failed_members", failed}};
  return py::make_tuple(arrays, report.dump());
}

#ifdef EPVIZ_HAVE_RENDER
// The RGBA frame as a (height, width, 4) uint8 array, or the failure (dict)
// that ended the frames before it.
py::object render_frame(const std::string& path, const std::string& object_json, long frame,
                        long width, long height, const std::string& gl) {
  job::RenderJob job = render_job(path, object_json, "epviz.render_frame");
  const auto in_range = [](const char* key, long v, long lo, long hi) {
    if (v < lo || v > hi)
      throw io::BadInput(std::string("epviz.render_frame: ") + key + ": expected an integer from " +
                         std::to_string(lo) + " to " + std::to_string(hi) + ", got " +
                         std::to_string(v));
  };
  if (width != 0) {
    in_range("width", width, 16, 8192);
    job.scene.width = int(width);
  }
  if (height != 0) {
    in_range("height", height, 16, 8192);
    job.scene.height = int(height);
  }
  const render::GlChoice choice(gl);
  const scene::ScenePlan plan = job::plan_job(job);
  in_range("frame", frame, 0, plan.frames - 1);
  paint::DrawnFrames drawn;
  {
    py::gil_scoped_release release;
    auto context = choice.open();
    paint::FramePainter painter(*context, job.scene.width, job.scene.height);
    const int frames[1] = {int(frame)};
    drawn = paint::draw_frames(plan, job.scene, frames, painter);
  }
  if (drawn.images.empty()) {
    if (drawn.failure) return failure_dict(*drawn.failure);
    throw std::runtime_error("epviz.render_frame: no frame was drawn");
  }
  auto image = std::move(drawn.images.front());
  auto* owned = new std::vector<std::uint8_t>(std::move(image.pixels));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<std::uint8_t>*>(p); });
  const auto h = std::size_t(image.height), w = std::size_t(image.width);
  return py::array_t<std::uint8_t>({h, w, std::size_t(4)}, {w * 4, std::size_t(4), std::size_t(1)},
                                   owned->data(), owner);
}
#endif

// The simulation fields as the job reader and `epviz simulate` know them
// (job/fields.hpp), for the Python layer's help and signature.
py::list field_table() {
  py::list out;
  for (const auto& f : job::simulation_field_table()) {
    py::dict d;
    d["key"] = f.key;
    d["flag"] = f.flag;
    const char* type = "str";
    switch (f.type) {
      case job::FieldType::text: type = "str"; break;
      case job::FieldType::vec3: type = "vec3"; break;
      case job::FieldType::number: type = "float"; break;
      case job::FieldType::integer: type = "int"; break;
      case job::FieldType::flag: type = "bool"; break;
    }
    d["type"] = type;
    d["default"] = f.default_value;
    d["help"] = f.help;
    d["choices"] = f.choices;
    d["range"] = f.range_text();
    out.append(d);
  }
  return out;
}

}  // namespace
}  // namespace epviz::python

PYBIND11_MODULE(_epviz, m) {
  using namespace epviz::python;
  m.doc() = "epviz's compiled core; use the package epviz, not this module.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const epviz::io::BadInput& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def("simulate", &simulate, py::arg("fields_json"), py::arg("max_steps") = py::none());
  m.def("section", &section, py::arg("path"), py::arg("object_json"), py::arg("threads"));
  m.def("cloud", &cloud, py::arg("path"), py::arg("object_json"), py::arg("threads"));
  m.def("sweep", &sweep, py::arg("path"), py::arg("object_json"), py::arg("threads"),
        py::arg("rows_file"));
#ifdef EPVIZ_HAVE_RENDER
  m.def("render_frame", &render_frame, py::arg("path"), py::arg("object_json"), py::arg("frame"),
        py::arg("width"), py::arg("height"), py::arg("gl"));
  m.attr("has_render") = true;
#else
  m.attr("has_render") = false;
#endif
  m.def("field_table", &field_table);
  m.def("simd_path", [] { return std::string(epviz::numerics::simd_path_report()); });
  m.attr("version") = EPVIZ_VERSION;
}
