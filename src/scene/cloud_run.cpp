#include "scene/cloud_run.hpp"

#include <Eigen/Geometry>  // cross()
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "numerics/failure.hpp"
#include "physics/stereographic.hpp"
#include "scene/plan.hpp"
#include "scene/plane_path.hpp"
#include "sim/methods.hpp"
#include "sim/run_options.hpp"

namespace epviz::scene {
namespace {

double kinetic(const physics::Body& body, const Eigen::Vector3d& omega) {
  return 0.5 * (body.inertia.array() * omega.array().square()).sum();
}

double potential(const physics::Body& body, const Eigen::Vector3d& gamma) {
  return body.weight * body.com.dot(gamma);
}

// Two unit vectors completing the unit vector g to an orthonormal frame.
void complete_frame(const Eigen::Vector3d& g, Eigen::Vector3d& e1, Eigen::Vector3d& e2) {
  const Eigen::Vector3d away =
      std::abs(g.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  e1 = g.cross(away).normalized();
  e2 = g.cross(e1);
}

}  // namespace

std::vector<physics::InitialState> cloud_members(const physics::Body& body,
                                                 const physics::InitialState& centre,
                                                 const CloudSettings& cloud) {
  const Eigen::Vector3d g0 = centre.gamma.normalized();
  Eigen::Vector3d e1, e2;
  complete_frame(g0, e1, e2);
  const double energy = kinetic(body, centre.omega) + potential(body, centre.gamma);
  const double t0 = kinetic(body, centre.omega);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  const double cap = 1.0 - std::cos(cloud.radius);
  std::vector<physics::InitialState> out;
  out.reserve(std::size_t(cloud.members));
  for (int k = 0; k < cloud.members; ++k) {
    const double c = 1.0 - cap * (double(k) + 0.5) / double(cloud.members);
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    const double phi = golden * double(k);
    physics::InitialState m;
    m.gamma = (c * g0 + s * (std::cos(phi) * e1 + std::sin(phi) * e2)).normalized();
    const double left = energy - potential(body, m.gamma);
    if (!(t0 > 0.0) || !(left > 0.0))
      throw PlanError(
          "cloud: its members keep the run's energy by scaling Omega, which needs the run's "
          "Omega non-zero and every member's potential energy below the run's energy; use a "
          "smaller \"radius\" or a faster Omega");
    m.omega = centre.omega * std::sqrt(left / t0);
    out.push_back(m);
  }
  return out;
}

double cloud_spread(const std::vector<Eigen::Vector3f>& points) {
  if (points.empty()) return 0.0;
  std::vector<int> count(kSpreadCells, 0);
  for (const auto& p : points) {
    // Bands equal in z are equal in area (Archimedes); sectors equal in longitude.
    const double z = std::clamp(double(p.z()), -1.0, 1.0);
    const int band = std::min(kSpreadBands - 1, int((z + 1.0) * 0.5 * kSpreadBands));
    const double lon = std::atan2(double(p.y()), double(p.x())) + M_PI;  // [0, 2 pi]
    const int sector = std::min(kSpreadSectors - 1, int(lon / (2.0 * M_PI) * kSpreadSectors));
    ++count[std::size_t(band * kSpreadSectors + sector)];
  }
  double h = 0.0;
  const double n = double(points.size());
  for (int c : count)
    if (c > 0) h -= (c / n) * std::log(c / n);
  return std::exp(h) / kSpreadCells;
}

void integrate_cloud(const sim::RunSpec& run, const CloudSettings& cloud,
                     const std::vector<double>& times, int threads, const CloudChunkSink& take) {
  const auto states = cloud_members(run.body, run.initial, cloud);
  const auto settings = sim::dop853_batch_settings(run);
  const double t_end = times.empty() ? 0.0 : times.back();
  for (std::size_t first = 0; first < states.size(); first += kCloudChunk) {
    const std::size_t last = std::min(states.size(), first + kCloudChunk);
    std::vector<sim::DirectBatchTask> tasks;
    tasks.reserve(last - first);
    for (std::size_t i = first; i < last; ++i) {
      tasks.push_back(sim::direct_batch_task(states[i], t_end, times));
      tasks.back().id = long(i);
    }
    take(first, sim::integrate_direct_batch_parallel(run.body, tasks, settings, threads));
  }
}

std::vector<double> cloud_times(const ScenePlan& plan) {
  std::vector<double> times;
  times.reserve(std::size_t(plan.frames));
  for (int i = 0; i < plan.frames; ++i) times.push_back(plan.frame_time(i));
  return times;
}

CloudRows cloud_rows(std::size_t first, const std::vector<sim::DirectBatchResult>& results,
                     std::size_t times) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CloudRows rows;
  rows.first = first;
  rows.members = results.size();
  rows.times = times;
  for (auto& c : rows.state) c.assign(results.size() * times, nan);
  rows.failure_t.assign(results.size(), nan);
  rows.failure_kind.resize(results.size());
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& outputs = results[i].outputs;
    for (std::size_t k = 0; k < outputs.size() && k < times; ++k)
      for (std::size_t c = 0; c < rows.state.size(); ++c)
        rows.state[c][i * times + k] = outputs[k][c];
    if (const auto& f = results[i].failure) {
      rows.failure_t[i] = f->t;
      rows.failure_kind[i] = std::string(numerics::name(f->kind));
      ++rows.failed;
    }
  }
  return rows;
}

CloudRun::CloudRun(const sim::RunSpec& run, const CloudSettings& cloud,
                   const std::vector<double>& frame_times, int threads)
    : members_(cloud.members), times_(frame_times), gamma_(frame_times.size()) {
  for (auto& g : gamma_) g.reserve(std::size_t(cloud.members));
  integrate_cloud(run, cloud, frame_times, threads,
                  [&](std::size_t, const std::vector<sim::DirectBatchResult>& results) {
                    // A member that failed is drawn up to its last output.
                    for (const auto& r : results)
                      for (std::size_t k = 0; k < r.outputs.size(); ++k) {
                        const auto& x = r.outputs[k];
                        gamma_[k].emplace_back(float(x[3]), float(x[4]), float(x[5]));
                      }
                  });
  spread_.reserve(gamma_.size());
  for (const auto& g : gamma_) spread_.push_back(cloud_spread(g));
}

CloudFrame CloudRun::frame(int index, float extent) const {
  CloudFrame f;
  f.members = members_;
  f.t_end = times_.empty() ? 0.0 : times_.back();
  f.sphere = gamma_at(index);
  f.plane.reserve(f.sphere.size());
  for (const auto& g : f.sphere)
    if (auto ab = physics::stereographic(g.cast<double>())) {
      const Eigen::Vector2f p = ab->cast<float>();
      if (inside_panel(p, extent)) f.plane.push_back(p);
    }
  f.spread.reserve(std::size_t(index) + 1);
  for (int k = 0; k <= index; ++k)
    f.spread.emplace_back(float(times_[std::size_t(k)]), float(spread_[std::size_t(k)]));
  return f;
}

}  // namespace epviz::scene
