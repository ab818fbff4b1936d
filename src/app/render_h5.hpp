#pragma once
// `epviz render JOB --h5 FILE`: a render's runs and its cloud as HDF5
// (h5/columns_file.hpp), beside its frames.
//
// Each run (the job's "simulation", or each of its "runs" in order) is a
// group run0, run1, ...: one float64 dataset per column of `epviz simulate
// --csv` (sweep::sample_column_names), chunked and written as the run goes.
// The run is integrated again for the file, from the very RunSpec the frames
// follow (the tolerance the plan chose included) by sim::simulate, the loop
// over sim::Trajectory that the frame source runs too: the same samples, to
// the job's end whatever --frames drew. Its attributes: label, method,
// formulation, accuracy, report (what `epviz simulate --report-json` says of
// it), failed, and failure (its line) when it failed; a failed run keeps the
// samples before its failure.
//
// The cloud, when the job has one, is a group "cloud" integrated as the
// frames' cloud is (scene::integrate_cloud): "t" (the frame times) and
// omega1..3, gamma1..3 as 2-D datasets [member, frame], NaN from a member's
// failure on; "failure_t" and "failure_kind" per member (NaN and "" for one
// that ran to the end).
//
// The root's attributes, as `simulate --h5` has them: job (the job as drawn,
// JSON), report (render's --report-json), epviz_version, simd_path, failed
// (1 when a run failed; a member of the cloud that fails does not fail the
// render) and failure (the first failed run's line).
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

#include "io/progress.hpp"
#include "job/job_file.hpp"
#include "scene/plan.hpp"

namespace epviz::app {

struct RenderH5Written {
  int runs = 0, failed_runs = 0;
  long cloud_members = 0, failed_members = 0;
  std::optional<std::string> failure;  // the first failed run's line
};

RenderH5Written write_render_h5(const std::string& path, const job::RenderJob& job,
                                const scene::ScenePlan& plan, const nlohmann::json& report,
                                const io::ProgressOptions& progress);

// The line printed after the file is written: "FILE: 3 runs (1 failed), a
// cloud of 10000 members (0 failed)".
std::string render_h5_summary(const std::string& path, const RenderH5Written& written);

}  // namespace epviz::app
