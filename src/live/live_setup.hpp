#pragma once
// Everything the user can set in the interactive scene: what is simulated (a
// sim::RunSpec), what is drawn (scene::SceneSettings) and how fast it plays.
// A render job converts to one (epviz serve JOB) and one converts back to a
// render job (job_file.hpp), so a setup found interactively can be rendered.
#include <filesystem>
#include <string>
#include <vector>

#include "job/document.hpp"
#include "live/compared_runs.hpp"
#include "scene/settings.hpp"
#include "sim/run_spec.hpp"

namespace epviz::live {

struct LiveSetup {
  sim::RunSpec run;
  scene::SceneSettings scene;
  double speed = 4.0;        // simulation time units per second of wall-clock time
  bool stay_in_case = true;  // edits keep the case's defining conditions
  // Further runs drawn with the first, as in a render job's "runs" (compared_runs.hpp).
  std::vector<ComparedRun> compared;
  std::string label;  // the first run's in a comparison's legend ("": its method names it)
};

// Runs at most in one scene, the first included: as many as a job's "runs" may hold.
inline constexpr int kMaxLiveRuns = job::max_runs;

// Case `c`'s preset body and state with the settings of its render job in
// render_jobs/ (body view, DOP853 with the tolerance from the resolution).
LiveSetup preset_setup(physics::Case c);

// The setup of a render job: `run` as resolved from its simulation fields, the
// speed that plays the job's t_end over its duration.
LiveSetup setup_from_job(const sim::RunSpec& run, const scene::SceneSettings& scene);

// The setup of the single render job in `file`, its "runs" (if any) as
// compared runs given in full. Throws io::BadInput for a gallery or
// bench-figures job, and what reading the job throws.
LiveSetup setup_from_job_file(const std::filesystem::path& file);

// The case's job from render_jobs/ when it is there (the same title, view,
// camera and trail as the rendered videos), else preset_setup(c); a job that
// cannot be read is reported on stderr and the preset used instead.
LiveSetup preset_from_jobs(physics::Case c);

}  // namespace epviz::live
