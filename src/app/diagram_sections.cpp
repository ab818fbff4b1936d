#include "app/diagram_sections.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "physics/invariants.hpp"
#include "physics/level_set.hpp"
#include "physics/notation.hpp"
#include "section/section_chart.hpp"

namespace epviz::app {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Vector4d = Eigen::Vector4d;

// The four conditions a start must meet, each divided by its scale:
// |γ|² − 1, C0 − area, C1 − energy, the fourth integral − its value.
Vector4d start_misses(const physics::DiagramRequest& r, const physics::ValuePoint& p,
                      const Vector6d& x, const Vector4d& scale) {
  const auto v = physics::invariants(r.body, r.case_id, x.head<3>(), x.tail<3>());
  return Vector4d(v.gamma_norm2 - 1.0, v.area - r.area, v.energy - p.energy,
                  v.extra.value_or(NAN) - p.integral)
      .cwiseQuotient(scale);
}

// Newton's method, least-norm steps (the four conditions leave two
// dimensions free), the Jacobian by central differences: the residual is
// evaluated exactly, so a rough Jacobian slows the convergence, not its end.
bool move_onto_value(const physics::DiagramRequest& r, const physics::ValuePoint& p,
                     physics::InitialState& s) {
  const auto sc = physics::invariant_scales(r.body, r.case_id, s.omega, s.gamma);
  const Vector4d scale(1.0, std::max(sc.area, 1e-300), std::max(sc.energy, 1e-300),
                       std::max(sc.extra.value_or(1.0), 1e-300));
  Vector6d x;
  x << s.omega, s.gamma;
  for (int iteration = 0; iteration < 40; ++iteration) {
    const Vector4d f = start_misses(r, p, x, scale);
    if (!f.allFinite()) return false;
    if (f.cwiseAbs().maxCoeff() <= 1e-13) {
      s.omega = x.head<3>(), s.gamma = x.tail<3>();
      return true;
    }
    Eigen::Matrix<double, 4, 6> jacobian;
    for (int i = 0; i < 6; ++i) {
      const double h = 1e-6 * std::max(1.0, std::abs(x[i]));
      Vector6d up = x, down = x;
      up[i] += h, down[i] -= h;
      jacobian.col(i) = (start_misses(r, p, up, scale) - start_misses(r, p, down, scale)) / (2 * h);
    }
    const Eigen::Matrix4d normal = jacobian * jacobian.transpose();
    Eigen::LDLT<Eigen::Matrix4d> solve(normal);
    if (solve.info() != Eigen::Success) return false;
    x -= jacobian.transpose() * solve.solve(f);
  }
  return false;
}

double state_distance(const physics::InitialState& a, const physics::InitialState& b) {
  return std::sqrt((a.omega - b.omega).squaredNorm() + (a.gamma - b.gamma).squaredNorm());
}

std::string section_point_number(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 4);
  return std::string(buf, r.ptr);
}

}  // namespace

std::vector<physics::InitialState> region_starts(const physics::DiagramRequest& request,
                                                 const physics::ValuePoint& point, int count) {
  if (count <= 0) return {};
  const physics::Level on{point.energy, request.area};
  std::vector<physics::InitialState> level = physics::level_states(request.body, on, 4000).states;
  if (level.empty()) level = physics::level_states_about_minimum(request.body, on, 4000).states;
  // The candidates: those whose integral is nearest the value.
  std::vector<std::pair<double, std::size_t>> nearest;
  for (std::size_t i = 0; i < level.size(); ++i) {
    const auto v =
        physics::invariants(request.body, request.case_id, level[i].omega, level[i].gamma);
    if (v.extra) nearest.push_back({std::abs(*v.extra - point.integral), i});
  }
  std::sort(nearest.begin(), nearest.end());
  nearest.resize(std::min<std::size_t>(nearest.size(), std::size_t(8 * count)));
  std::vector<physics::InitialState> moved;
  for (const auto& [miss, i] : nearest) {
    physics::InitialState s = level[i];
    if (move_onto_value(request, point, s)) moved.push_back(s);
  }
  if (moved.empty()) return {};
  // Spread: the first the one that started nearest, then each the farthest
  // from those taken.
  std::vector<physics::InitialState> taken{moved.front()};
  std::vector<double> gap(moved.size(), INFINITY);
  while (int(taken.size()) < count) {
    std::size_t best = 0;
    for (std::size_t i = 0; i < moved.size(); ++i) {
      gap[i] = std::min(gap[i], state_distance(moved[i], taken.back()));
      if (gap[i] > gap[best]) best = i;
    }
    if (!(gap[best] > 1e-9)) break;  // every candidate is one already taken
    taken.push_back(moved[best]);
  }
  return taken;
}

section::SectionJob region_section_job(const physics::DiagramRequest& request,
                                       std::vector<physics::InitialState> starts, int crossings,
                                       const std::string& csv, int surface) {
  using sim::StateComponent;
  // γ₃ = 0 upward with axes (γ₁, Ω₃) and sheets by γ₂, as the shipped
  // sections; the others its cyclic turns (1 -> 2 -> 3 -> 1 of the indices).
  static constexpr std::array<std::array<StateComponent, 4>, 3> kSurfaces{{
      {StateComponent::gamma3, StateComponent::gamma1, StateComponent::omega3,
       StateComponent::gamma2},
      {StateComponent::gamma1, StateComponent::gamma2, StateComponent::omega1,
       StateComponent::gamma3},
      {StateComponent::gamma2, StateComponent::gamma3, StateComponent::omega2,
       StateComponent::gamma1},
  }};
  const auto& choice = kSurfaces[std::size_t(std::clamp(surface, 0, 2))];
  section::SectionJob job;
  job.file = "epviz diagram --sections";
  job.case_id = request.case_id;
  job.body = request.body;
  job.states = std::move(starts);
  job.crossings = crossings;
  job.t_end = 1e4;
  job.surface.function = choice[0];
  job.surface.value = 0.0;
  job.surface.direction = sim::CrossingDirection::upward;
  job.coords[0] = choice[1];
  job.coords[1] = choice[2];
  job.sheet = section::SheetChoice{choice[3], section::SheetChoice::Show::both_apart};
  job.csv = csv;
  return job;
}

int region_surface(const physics::DiagramRequest& request,
                   const std::vector<physics::InitialState>& starts, int threads) {
  int best = 0;
  std::size_t most = 0;
  for (int surface = 0; surface < 3; ++surface) {
    section::SectionJob probe = region_section_job(request, starts, 3, "", surface);
    probe.t_end = 200.0;
    const auto results = section::run_section(probe, starts, threads);
    std::size_t found = 0;
    bool every = true;
    for (const auto& r : results) {
      if (r.failure) continue;  // the section proper reports it
      found += r.crossings.size();
      every = every && r.crossings.size() == 3;
    }
    if (every) return surface;
    if (found > most) best = surface, most = found;
  }
  return best;
}

chart::Figure region_section_figure(const physics::DiagramRequest& request,
                                    const DiagramRegion& region, const section::SectionJob& job,
                                    const std::vector<section::OrbitResult>& orbits) {
  chart::ChartSpec c;
  c.title = "Region ";
  c.title += region.label;
  c.title += " of the diagram: ";
  c.title += physics::symbol::energy;
  c.title += " = " + section_point_number(region.point.energy) + ", ";
  c.title += physics::integral_symbol(request.case_id);
  c.title += " = " + section_point_number(region.point.integral) + ", ";
  c.title += physics::symbol::area;
  c.title += " = " + section_point_number(request.area) + " (" + std::to_string(job.states.size()) +
             " orbits)";
  c.panels = section::section_charts(job, orbits);
  c.panel_columns = int(c.panels.size());
  return {"section_" + region.label + ".png", std::move(c)};
}

}  // namespace epviz::app
