#pragma once
// A render job as its file states it (render_jobs/*.json), before the
// simulation fields are checked against physics: what job/schema.hpp reads
// from a file and writes to one.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/print_size.hpp"
#include "io/video_format.hpp"
#include "scene/settings.hpp"

namespace epviz::job {

// A value the job (or the command line) gave, and where, for messages
// ("--inertia", "job.json: key 'simulation.inertia'").
template <class T>
struct Given {
  std::optional<T> value;
  std::string origin;
  explicit operator bool() const { return value.has_value(); }
  const T& operator*() const { return *value; }
  void set(T v, std::string from) {
    value = std::move(v);
    origin = std::move(from);
  }
};

// The fields that describe a simulation: the same names on the command line
// (`epviz simulate --inertia`) and in a job's "simulation" object.
struct SimulationFields {
  Given<std::string> case_name;
  Given<std::array<double, 3>> inertia, com, omega, gamma;
  Given<double> weight, tol, step, t_end, max_drift;
  Given<long> samples;
  Given<std::string> formulation, method;
  Given<bool> allow_nonphysical, normalize_gamma, chart_switch;

  // Fields given in `over` replace those here (the command line over a job file).
  void overlay(const SimulationFields& over);
};

// A render writes PNG frames or a video in one of io::VideoFormat's formats;
// "png" is the one format name the job adds to the videos' names.
// "png", then the video formats' names.
std::vector<std::string> output_format_names();
// "png" without a video format, else the video format's name.
std::string_view output_format_name(const std::optional<io::VideoFormat>& video);
// A format named on the command line by `option`: none for "png". Throws
// io::BadInput naming the option and the formats allowed.
std::optional<io::VideoFormat> parse_output_format(const std::string& option,
                                                   const std::string& name);

struct OutputSettings {
  std::filesystem::path dir = "out";
  std::optional<io::VideoFormat> video;  // empty: PNG frames
  std::string
      name;  // video file stem, or PNG frame prefix ("frame" -> frame_0042.png); empty: not given
  // "figure_width", "font_size", "dpi": a figure at a printed size, as the
  // file gives them (each checked on reading; "" where not given). The
  // command's options of the same names go over them.
  io::PrintSizeText print;
};

// One run of a comparison scene (a job's "runs" list): a label and the
// simulation fields that replace the job's own for this run.
struct RunFields {
  std::string label;            // empty: not given (the run is named by its method)
  SimulationFields simulation;  // over the job's "simulation"
  bool auto_tolerance = false;  // "tol": "auto" in this run
};

// Runs at most in one comparison scene: each has its own colour and legend row.
inline constexpr int max_runs = 6;

struct JobDocument {
  SimulationFields simulation;
  std::vector<RunFields> runs;  // empty: the one run of "simulation"
  scene::SceneSettings scene;   // auto_tolerance: "tol" is "auto" or absent
  OutputSettings output;
};

}  // namespace epviz::job
