#pragma once
// The job files `epviz render` takes are the job format's (job/job_file.hpp).
#include "app/simulation_fields.hpp"  // resolve(), which every user of a job calls
#include "job/job_file.hpp"

namespace epviz::app {

using job::BenchFiguresJob;
using job::GalleryJob;
using job::LoadedJob;
using job::output_format_from_name;
using job::output_format_name;
using job::OutputFormat;
using job::OutputSettings;
using job::RenderJob;

inline LoadedJob load_render_job(const std::filesystem::path& path) {
  return job::load_job_file(path);
}

}  // namespace epviz::app
