#include "app/job_frames.hpp"

#include "app/usage_error.hpp"

#include <cmath>

namespace epviz::app {

namespace {

// The runs a job asks for: its "simulation", or each of its "runs" over it.
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

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace

scene::ScenePlan plan_job(const RenderJob& job) {
  auto requests = run_requests(job);
  try {
    return scene::plan_scene(std::move(requests), job.scene);
  } catch (const scene::PlanError& e) {
    throw UsageError(job.file.string() + ": " + e.what());
  }
}

std::string tile_caption(const RenderJob& job, const scene::ScenePlan& plan) {
  std::string s = job.file.stem().string() + ": " + std::string(sim::name(plan.run.method)) + ", " +
                  plan.accuracy_note;
  if (plan.comparison()) s += " (+" + std::to_string(plan.others.size()) + " runs)";
  return s;
}

nlohmann::json runs_report(const scene::FrameSource& source) {
  const auto& plan = source.plan();
  nlohmann::json runs = nlohmann::json::array();
  for (int i = 0; i < source.run_count(); ++i) {
    const auto& track = source.run(i);
    const auto& spec = track.spec();
    const auto stats = track.trajectory().stats();
    nlohmann::json j;
    j["label"] = i == 0 ? plan.label : plan.others[std::size_t(i - 1)].label;
    j["method"] = std::string(sim::name(spec.method));
    j["formulation"] = std::string(sim::name(spec.formulation));
    if (sim::is_adaptive(spec.method)) {
      j["tol"] = spec.tol;
      j["effective_step"] = nullptr;
    } else {
      j["tol"] = nullptr;
      j["effective_step"] = track.trajectory().effective_step();
    }
    j["steps"] = stats.steps;
    j["rejected_steps"] = stats.rejected_steps;
    j["rhs_evals"] = stats.rhs_evals;
    j["flow_evals"] = stats.flow_evals;
    j["interpolation_evals"] = track.trajectory().interpolation_evals();
    j["t_reached"] = track.latest().t;
    const auto& d = track.max_drift();
    nlohmann::json drift = {{"gamma_norm2", number_or_null(d.gamma_norm2)},
                            {"area", number_or_null(d.area)},
                            {"energy", number_or_null(d.energy)}};
    drift["extra_integral"] = d.extra ? number_or_null(*d.extra) : nlohmann::json(nullptr);
    j["max_relative_drift"] = std::move(drift);
    // null: pixel-true over the whole run drawn (or not checked: "shadowed" says which).
    j["shadowed"] = track.shadowed();
    j["pixel_true_until"] = track.pixel_true_until() ? nlohmann::json(*track.pixel_true_until())
                                                     : nlohmann::json(nullptr);
    j["max_error_px"] = track.max_error_px();
    runs.push_back(std::move(j));
  }
  return runs;
}

JobFrameDrawer::JobFrameDrawer(const scene::ScenePlan& plan, const scene::SceneSettings& settings)
    : source_(plan, settings) {}

const render::RgbaImage& JobFrameDrawer::draw(int index, paint::FramePainter& painter,
                                              std::mutex* paint_lock) {
  scene::Frame frame = source_.frame(index);
  frame.caption = caption_;
  if (!paint_lock) return painter.paint(frame);
  std::lock_guard lock(*paint_lock);
  return painter.paint(frame);
}

RenderedFrames render_job_frames(const scene::ScenePlan& plan, const scene::SceneSettings& settings,
                                 std::span<const int> frames, paint::FramePainter& painter,
                                 std::mutex* paint_lock) {
  RenderedFrames out;
  JobFrameDrawer drawer(plan, settings);
  try {
    for (const int i : frames) {
      // Copied: the painter's next paint overwrites its image.
      out.images.push_back(drawer.draw(i, painter, paint_lock));
    }
  } catch (const numerics::IntegrationError& e) {
    out.failure = e.failure();
  }
  return out;
}

}  // namespace epviz::app
