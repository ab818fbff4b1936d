#pragma once
// The render jobs a list of paths names (`epviz check JOB...`): job files,
// galleries (each of their jobs) and directories (their *.json files in name
// order; bench-figures jobs, sweeps and sections skipped), each job once.
#include <string>
#include <utility>
#include <vector>

#include "job/job_file.hpp"

namespace epviz::job {

// Each job with the name it is shown by: the path given, or for a job of a
// gallery its own file. Throws io::BadInput for a bench-figures job named
// directly and for a directory without *.json files.
std::vector<std::pair<RenderJob, std::string>> render_jobs_in(const std::vector<std::string>& args);

}  // namespace epviz::job
