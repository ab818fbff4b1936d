#pragma once
// The current interactive setup as a render job (render_jobs/*.json format)
// that `epviz render` accepts: the same body, state, integrator, camera and
// view, at the live speed. A live run starts at t = 0, as render jobs do (the
// format has no start time), so the job covers what the user watched: from
// t = 0 to the moment shown, its video ending on that moment.
#include <string>

#include "job/document.hpp"
#include "live/live_setup.hpp"

namespace epviz::live {

// What the live scene runs with beyond its setup.
struct LiveMoment {
  double time = 0.0;  // the simulation time shown
  // The tolerance of an adaptive method with the automatic tolerance: the
  // one the live run uses (for its long horizon), which a render of a
  // shorter run would choose looser. Unset: the setup's own.
  std::optional<double> tolerance;
};

// The job's content. `name` is the output stem (out/<name>/...). The body and
// state are given in full, so the job reproduces an edited body; the case is
// named only when its conditions hold (else the run is a custom body). The
// tolerance or step is written as a number, never "auto". Before anything
// was watched (moment.time 0) the job runs `duration_s` of video at the
// live speed instead.
job::JobDocument job_document(const LiveSetup& setup, const std::string& name,
                              const LiveMoment& moment = {}, double duration_s = 10.0);

// job_document written in the job format (job/schema.hpp).
std::string render_job_json(const LiveSetup& setup, const std::string& name,
                            const LiveMoment& moment = {}, double duration_s = 10.0);

// Throws io::BadInput with the message `epviz render` would give when it
// would refuse the job `text` (the file `file_name`): read by the job reader,
// its runs resolved and planned, its output name and video size checked, as
// `epviz render` does before any work. What "Save job" sends passes this.
void check_render_accepts(const std::string& text, const std::string& file_name);

// The tolerance the live scene runs `setup` with (its plan for an open-ended
// run), or nullopt when the method has a fixed step or the tolerance is set.
std::optional<double> live_tolerance(const LiveSetup& setup);

}  // namespace epviz::live
