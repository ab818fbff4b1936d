#include "scene/cloud_run.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "physics/stereographic.hpp"
#include "scene/plan.hpp"
#include "scene/plane_path.hpp"
#include "sim/methods.hpp"
#include "sim/run_options.hpp"

namespace epviz::scene {
namespace {

// Integrated this many members at a time: their outputs at every frame time
// (6 doubles each) are turned into floats before the next chunk.
constexpr std::size_t kChunk = 1024;

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

CloudRun::CloudRun(const sim::RunSpec& run, const CloudSettings& cloud,
                   const std::vector<double>& frame_times, int threads)
    : members_(cloud.members), times_(frame_times), gamma_(frame_times.size()) {
  const auto states = cloud_members(run.body, run.initial, cloud);
  // DOP853 in the direct formulation, whatever the run's own method and
  // formulation (the batch path has that one only), at sim::adaptive_tol.
  const auto settings = sim::dop853_batch_settings(run);
  const double t_end = frame_times.empty() ? 0.0 : frame_times.back();
  for (auto& g : gamma_) g.reserve(states.size());
  for (std::size_t first = 0; first < states.size(); first += kChunk) {
    const std::size_t last = std::min(states.size(), first + kChunk);
    std::vector<sim::DirectBatchTask> tasks;
    tasks.reserve(last - first);
    for (std::size_t i = first; i < last; ++i) {
      tasks.push_back(sim::direct_batch_task(states[i], t_end, frame_times));
      tasks.back().id = long(i);
    }
    const auto results = sim::integrate_direct_batch_parallel(run.body, tasks, settings, threads);
    // A member that failed is drawn up to its last output.
    for (const auto& r : results)
      for (std::size_t k = 0; k < r.outputs.size(); ++k) {
        const auto& x = r.outputs[k];
        gamma_[k].emplace_back(float(x[3]), float(x[4]), float(x[5]));
      }
  }
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
