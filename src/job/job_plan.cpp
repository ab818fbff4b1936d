#include "job/job_plan.hpp"

#include "io/bad_input.hpp"
#include "job/resolve.hpp"
#include "scene/cloud_run.hpp"
#include "sim/methods.hpp"

namespace epviz::job {

std::vector<scene::RunRequest> run_requests(const RenderJob& job) {
  std::vector<scene::RunRequest> requests;
  if (job.runs.empty()) {
    requests.push_back(
        {resolve(job.simulation), "", job.scene.formulation_given, job.scene.auto_tolerance});
    return requests;
  }
  for (const auto& r : job.runs) {
    SimulationFields fields = job.simulation;
    fields.overlay(r.simulation);
    // A run that picks its own method drops the job's accuracy setting of the
    // other kind (the job's step for an adaptive run, its tol for a fixed one).
    if (r.simulation.method)
      if (auto m = sim::method_from_name(*r.simulation.method)) {
        if (sim::is_adaptive(*m) && !r.simulation.step) fields.step = {};
        if (!sim::is_adaptive(*m) && !r.simulation.tol) fields.tol = {};
      }
    scene::RunRequest q;
    q.run = resolve(fields);
    q.label = r.label;
    q.formulation_given = fields.formulation.value.has_value();
    // A run's own "tol" (a number or "auto") decides; else the job's.
    q.auto_tolerance = r.auto_tolerance || (!r.simulation.tol && job.scene.auto_tolerance);
    requests.push_back(std::move(q));
  }
  return requests;
}

scene::ScenePlan plan_job(const RenderJob& job) {
  auto requests = run_requests(job);
  try {
    auto plan = scene::plan_scene(std::move(requests), job.scene);
    // The cloud's members, checked before any work (they must keep the run's energy).
    if (job.scene.cloud.enabled())
      (void)scene::cloud_members(plan.run.body, plan.run.initial, job.scene.cloud);
    return plan;
  } catch (const scene::PlanError& e) {
    throw io::BadInput(job.file.string() + ": " + e.what());
  }
}

std::string tile_caption(const RenderJob& job, const scene::ScenePlan& plan) {
  std::string s = job.file.stem().string() + ": " + std::string(sim::name(plan.run.method)) + ", " +
                  plan.accuracy_note;
  if (plan.comparison()) s += " (+" + std::to_string(plan.others.size()) + " runs)";
  return s;
}

}  // namespace epviz::job
