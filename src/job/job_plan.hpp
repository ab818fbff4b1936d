#pragma once
// A render job's scene plan: its runs resolved (job/resolve.hpp) and planned
// for its picture (scene/plan.hpp). Shared by `epviz render`, `epviz check`
// and the gallery's tiles.
#include <string>
#include <vector>

#include "job/job_file.hpp"
#include "scene/plan.hpp"

namespace epviz::job {

// The runs `job` asks for, resolved: its "simulation", or each of its "runs"
// over it. Throws io::BadInput naming the field.
std::vector<scene::RunRequest> run_requests(const RenderJob& job);

// The scene plan of `job` (simulation resolved, tolerance chosen for its
// resolution). Throws io::BadInput naming the job file when it cannot be drawn.
scene::ScenePlan plan_job(const RenderJob& job);

// A gallery tile's caption: the job's name, method and accuracy.
std::string tile_caption(const RenderJob& job, const scene::ScenePlan& plan);

}  // namespace epviz::job
