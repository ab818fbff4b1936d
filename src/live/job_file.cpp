#include "live/job_file.hpp"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace epviz::live {
namespace {

nlohmann::json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

std::string hex_colour(const scene::Rgba& c) {
  auto byte = [](float x) { return int(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); };
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x%02x", byte(c[0]), byte(c[1]), byte(c[2]), byte(c[3]));
  return buf;
}

}  // namespace

std::string render_job_json(const LiveSetup& setup, const std::string& name, double duration_s) {
  const auto& run = setup.run;
  const auto& s = setup.scene;
  nlohmann::ordered_json sim;
  if (run.case_id != physics::Case::custom) sim["case"] = physics::case_name(run.case_id);
  sim["inertia"] = vec(run.body.inertia);
  sim["com"] = vec(run.body.com);
  sim["weight"] = run.body.weight;
  sim["omega"] = vec(run.initial.omega);
  sim["gamma"] = vec(run.initial.gamma);
  sim["formulation"] = std::string(sim::name(run.formulation));
  sim["method"] = std::string(sim::name(run.method));
  if (sim::is_adaptive(run.method)) {
    if (s.auto_tolerance)
      sim["tol"] = "auto";
    else
      sim["tol"] = run.tol;
  } else {
    sim["step"] = run.step;
  }
  if (run.formulation == sim::Formulation::riccati) sim["chart_switch"] = run.chart_switch;
  sim["t_end"] = setup.speed * duration_s;

  nlohmann::ordered_json job;
  if (!s.title.empty()) job["title"] = s.title;
  job["simulation"] = sim;
  job["view"] = s.view == scene::View::space ? "space" : "body";
  job["camera"] = {{"azimuth", s.camera.azimuth_deg}, {"elevation", s.camera.elevation_deg},
                   {"distance", s.camera.distance}};
  job["layers"] = {{"body", s.layers.body}, {"sphere", s.layers.sphere}, {"riccati", s.layers.riccati},
                   {"overlay", s.layers.overlay}};
  job["colours"] = {{"background", hex_colour(s.colours.background)}, {"body", hex_colour(s.colours.body)},
                    {"sphere", hex_colour(s.colours.sphere)}, {"marker", hex_colour(s.colours.marker)}};
  if (s.trail_length > 0.0) job["trail"] = {{"length", s.trail_length}};
  job["plane"] = {{"extent", s.plane_extent}};
  job["width"] = s.width;
  job["height"] = s.height;
  job["fps"] = 30;
  job["duration"] = duration_s;
  job["output"] = {{"dir", "out/" + name}, {"format", "mp4"}, {"name", name}};
  return job.dump(2) + "\n";
}

}  // namespace epviz::live
