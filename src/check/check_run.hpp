#pragma once
// A whole `epviz check` run: the jobs' frames drawn on worker threads, each
// with a FrameSource of its own, and checked as they come (job_check.hpp);
// each job's lines printed in job order, whatever the number of workers; the
// summary, the HTML report and the JUnit file; the exit code. Drawing is
// behind an interface, so the run knows no GL and tests drive it with images
// of their own.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "check/golden_files.hpp"
#include "check/tolerance.hpp"

namespace epviz::check {

// The exit codes of `epviz check` (docs/ci.md). 2, bad input, is every
// command's (io::BadInput); 3 and 4 mean other things to other commands.
constexpr int kExitPassed = 0;
constexpr int kExitFrameFailed = 1;
// The check could not be done: a file could not be written, or nothing can
// draw here (no GL, no font). Not a verdict on any frame.
constexpr int kExitCannotCheck = 5;

// Draws frames on one worker thread.
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // What draws: recorded in golden.json, compared with it.
  virtual const RenderEnvironment& environment() const = 0;
  // Draws the frames of job `job` (job.frames, increasing), each handed to
  // `on_frame` as soon as it is drawn (valid during the call). Returns why
  // the frames ended early (a numerical failure), or nullopt.
  virtual std::optional<std::string> draw(
      std::size_t index, const GoldenJob& job,
      const std::function<void(const ImageView&)>& on_frame) = 0;
};

// Makes a worker's FrameSource, on that worker's thread; throws when nothing
// can draw here.
using FrameSourceFactory = std::function<std::unique_ptr<FrameSource>()>;

struct RunSettings {
  Tolerance tolerance;
  bool update = false;  // make the frames the goldens instead of comparing
  int workers = 1;
  std::filesystem::path report_dir;  // empty: no HTML report (none with update)
  std::filesystem::path junit;       // empty: no JUnit file
  std::string epviz_version;         // recorded in golden.json
  // The command that re-creates the goldens of `frames` of `job`.
  std::function<std::string(const GoldenJob& job, const std::vector<int>& frames)> update_command;
};

// Throws io::BadInput when --report names a file or a folder whose parent is
// missing, or --junit no file that can be written (io::check_output_file).
// Either may be empty (not given).
void check_output_paths(const std::string& report, const std::string& junit);

// Checks (or, with settings.update, re-baselines) `jobs`, whose inputs are
// already looked at (golden_job) and whose report folder exists. Prints each
// job's lines in job order to `out` and its warnings to `err`, then the
// summary, and writes the report and the JUnit file. Returns kExitPassed or
// kExitFrameFailed; when a source cannot be made or a file cannot be written,
// one line on `err` ("epviz: error: ...") and kExitCannotCheck. io::BadInput
// is passed on.
int run_checks(std::span<const GoldenJob> jobs, const RunSettings& settings,
               const FrameSourceFactory& make_source, std::ostream& out, std::ostream& err);

}  // namespace epviz::check
