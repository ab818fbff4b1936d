#pragma once
// The current interactive setup as a render job (render_jobs/*.json format)
// that `epviz render` accepts: the same body, state, integrator and view, a
// video of `duration` seconds at the live speed.
#include <string>

#include "job/document.hpp"
#include "live/live_setup.hpp"

namespace epviz::live {

// The job's content. `name` is the output stem (out/<name>/...). The body and
// state are given in full, so the job reproduces an edited body; the case is
// named only when its conditions hold (else the run is a custom body).
job::JobDocument job_document(const LiveSetup& setup, const std::string& name,
                              double duration_s = 10.0);

// job_document written in the job format (job/schema.hpp).
std::string render_job_json(const LiveSetup& setup, const std::string& name,
                            double duration_s = 10.0);

}  // namespace epviz::live
