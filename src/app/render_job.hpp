#pragma once
// Old names of the job format's (job/job_file.hpp, job/resolve.hpp), kept only
// for bench_command.cpp until it includes those headers itself.
#include "job/job_file.hpp"
#include "job/resolve.hpp"

namespace epviz::app {

using job::LoadedJob;
using job::resolve;

inline LoadedJob load_render_job(const std::filesystem::path& path) {
  return job::load_job_file(path);
}

}  // namespace epviz::app
