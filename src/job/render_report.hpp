#pragma once
// What `epviz render --report-json` says of a job after its frames: the job,
// its run's method and accuracy, the frames drawn and the time taken, the
// failure if any, and each run's work, drifts and pixel-true horizon.
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>

#include "job/job_file.hpp"
#include "numerics/failure.hpp"
#include "scene/frame_source.hpp"
#include "scene/plan.hpp"
#include "sim/drift.hpp"

namespace epviz::job {

// The frames of a job that were drawn or skipped (--resume), in how long.
struct RenderCounts {
  int frames_drawn = 0, frames_skipped = 0;
  double seconds = 0.0;
  std::optional<numerics::Failure> failure;
};

// Per run of a scene after its frames: method, the step used (fixed) or
// tolerance (adaptive), steps, evaluations, its two drifts (sim::RunDrifts:
// "max_relative_drift" over the samples drawn, as in simulate's report and a
// sweep's rows, and "step_drift" at the integrator's steps), and its
// pixel-true horizon.
nlohmann::json runs_report(const scene::FrameSource& source);

// A report's object of the largest relative drift of each invariant
// (gamma_norm2, area, energy, extra_integral; null where none or not finite):
// render's and simulate's "step_drift".
nlohmann::json drift_json(const sim::Drifts& d);

// The job's report; `runs` is runs_report() after its last frame (its first
// run's step and pixel-true horizon are repeated at the top level).
nlohmann::json render_report(const RenderJob& job, const scene::ScenePlan& plan,
                             const RenderCounts& counts, const nlohmann::json& runs);

// The line `epviz render` prints after a job: "job.json: 6 frames 320x240
// in 0.41 s (14.6 frames/s), dop853 tol auto ..., spinor -> out".
std::string render_summary(const RenderJob& job, const scene::ScenePlan& plan,
                           const RenderCounts& counts);

}  // namespace epviz::job
