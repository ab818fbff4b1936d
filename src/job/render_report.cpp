#include "job/render_report.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "physics/cases.hpp"
#include "sim/failure_advice.hpp"
#include "sim/methods.hpp"

namespace epviz::job {
namespace {

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json drift_json(const sim::Drifts& d) {
  nlohmann::json j = {{"gamma_norm2", number_or_null(d.gamma_norm2)},
                      {"area", number_or_null(d.area)},
                      {"energy", number_or_null(d.energy)}};
  j["extra_integral"] = d.extra ? number_or_null(*d.extra) : nlohmann::json(nullptr);
  return j;
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
    j["max_relative_drift"] = drift_json(track.drifts().output);
    j["step_drift"] = drift_json(track.drifts().steps);
    // null: pixel-true over the whole run drawn (or not checked: "shadowed" says which).
    j["shadowed"] = track.shadowed();
    j["pixel_true_until"] = track.pixel_true_until() ? nlohmann::json(*track.pixel_true_until())
                                                     : nlohmann::json(nullptr);
    j["max_error_px"] = track.max_error_px();
    runs.push_back(std::move(j));
  }
  return runs;
}

nlohmann::json render_report(const RenderJob& job, const scene::ScenePlan& plan,
                             const RenderCounts& counts, const nlohmann::json& runs) {
  const auto& run = plan.run;
  const auto& failure = counts.failure;
  nlohmann::json j;
  j["job"] = job.file.string();
  j["case"] = physics::case_name(run.case_id);
  j["formulation"] = std::string(sim::name(run.formulation));
  j["method"] = std::string(sim::name(run.method));
  j["accuracy"] = plan.accuracy_note;
  if (sim::is_adaptive(run.method)) j["tol"] = run.tol;
  j["frames"] = plan.frames;
  j["frames_drawn"] = counts.frames_drawn;
  j["frames_skipped"] = counts.frames_skipped;
  j["seconds"] = counts.seconds;
  j["output"] = job.output.dir.string();
  j["failure"] = failure ? nlohmann::json(sim::failure_line(*failure, sim::SettingsIn::render_job))
                         : nlohmann::json(nullptr);
  j["failure_kind"] = failure ? nlohmann::json(std::string(numerics::name(failure->kind)))
                              : nlohmann::json(nullptr);
  if (runs.is_array() && !runs.empty()) {
    j["effective_step"] = runs[0]["effective_step"];
    j["pixel_true_until"] = runs[0]["pixel_true_until"];
    j["runs"] = runs;
  }
  return j;
}

std::string render_summary(const RenderJob& job, const scene::ScenePlan& plan,
                           const RenderCounts& counts) {
  const double seconds = counts.seconds;
  char rate[64];
  std::snprintf(rate, sizeof rate, " in %.2f s (%.1f frames/s), ", seconds,
                seconds > 0 ? counts.frames_drawn / seconds : 0.0);
  std::string line = job.file.string() + ": ";
  line += std::to_string(counts.frames_drawn) + " frames " + std::to_string(job.scene.width) + "x" +
          std::to_string(job.scene.height);
  line += rate;
  // Each run's method, accuracy and formulation: a comparison names every run
  // it drew, numbered as in its legend, not the first alone.
  const auto setting = [](const sim::RunSpec& run, const std::string& note) {
    return std::string(sim::name(run.method)) + " " + note + ", " +
           std::string(sim::name(run.formulation));
  };
  if (!plan.comparison()) {
    line += setting(plan.run, plan.accuracy_note);
  } else {
    line += "run 1 " + setting(plan.run, plan.accuracy_note);
    for (std::size_t k = 0; k < plan.others.size(); ++k)
      line += "; run " + std::to_string(k + 2) + " " +
              setting(plan.others[k].run, plan.others[k].accuracy_note);
  }
  line += " -> " + job.output.dir.string() + "\n";
  return line;
}

}  // namespace epviz::job
