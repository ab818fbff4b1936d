#include "sweep/level_point.hpp"

#include <algorithm>
#include <cmath>

#include "io/json_line.hpp"
#include "physics/admissible.hpp"
#include "physics/invariants.hpp"
#include "physics/level_set.hpp"
#include "sim/simulate.hpp"

namespace epviz::sweep {
namespace {

// Up to `orbits` states of the level, spread over it. Near the admissible
// boundary only a small cap of directions carries a state, which a grid of
// `orbits` directions may miss: the grid is refined fourfold until `orbits`
// directions carry one (at most 256 x `orbits` directions), and `orbits` of
// those, evenly spaced along the spiral, are kept; when even the finest grid
// meets none, the states of physics::level_states_about_minimum.
std::vector<physics::InitialState> spread_states(const physics::Body& body,
                                                 const physics::Level& level, int orbits) {
  std::vector<physics::InitialState> all;
  for (int n = orbits;; n *= 4) {
    all = physics::level_states(body, level, n).states;
    if (int(all.size()) >= orbits || n >= 256 * orbits) break;
  }
  // Closer still to the least energy, the caps about the minimiser.
  if (all.empty()) all = physics::level_states_about_minimum(body, level, orbits).states;
  if (int(all.size()) <= orbits) return all;
  std::vector<physics::InitialState> kept;
  for (int i = 0; i < orbits; ++i)
    kept.push_back(all[std::size_t(long(i) * long(all.size()) / orbits)]);
  return kept;
}

}  // namespace

LevelMetrics level_metrics(const sim::RunSpec& run, const physics::Level& level, int orbits,
                           const FtleSettings& ftle) {
  const double cpu_start = sim::thread_cpu_seconds();
  LevelMetrics m;
  m.minimum_energy = physics::minimum_energy(run.body, level.area).energy;
  m.admissible = level.energy >= m.minimum_energy;
  if (!m.admissible) return m;
  const auto states = spread_states(run.body, level, orbits);
  m.orbits = int(states.size());
  int measured = 0;
  for (const auto& start : states) {
    sim::RunSpec one = run;
    one.initial = start;
    const auto scales =
        physics::invariant_scales(run.body, run.case_id, start.omega, start.gamma).extra;
    double k_lo = HUGE_VAL, k_hi = -HUGE_VAL;
    auto track = [&](const FtleState& x) {
      if (const auto k =
              physics::invariants(run.body, run.case_id, x.head<3>(), x.tail<3>()).extra) {
        k_lo = std::min(k_lo, *k);
        k_hi = std::max(k_hi, *k);
      }
    };
    track((FtleState() << start.omega, start.gamma).finished());
    const auto lambda = finite_time_lyapunov(one, ftle, track);
    if (!lambda) {
      ++m.lost;
      continue;
    }
    ++measured;
    m.largest_ftle = std::max(m.largest_ftle.value_or(-HUGE_VAL), *lambda);
    const std::optional<double> k_range =
        scales && k_hi >= k_lo ? std::optional<double>((k_hi - k_lo) / *scales) : std::nullopt;
    if (k_range) m.extra_integral_range = std::max(m.extra_integral_range.value_or(0.0), *k_range);
    if (*lambda > kChaoticFtle) {
      if (!scales)
        ++m.chaotic;  // no fourth integral: the FTLE decides
      else if (k_range && *k_range <= kKeptIntegral)
        ++m.hyperbolic;  // confined by the fourth integral: not chaos
      else
        ++m.undecided;
    }
  }
  if (const int decided = measured - m.undecided; decided > 0)
    m.chaotic_share = double(m.chaotic) / double(decided);
  m.cpu_seconds = sim::thread_cpu_seconds() - cpu_start;
  return m;
}

PointRow level_row(const PreparedPoint& point, const std::string& sweep_hash,
                   const LevelMetrics& m) {
  const sim::RunSpec& run = point.run;
  io::JsonLine row;
  begin_row(row, point, sweep_hash);
  row.key("case").value(physics::case_name(run.case_id));
  row.key("method").value(sim::name(run.method));
  if (sim::is_adaptive(run.method))
    row.key("tol").value(run.tol);
  else
    row.key("step").value(run.step);
  row.key("t_end").value(run.t_end);
  row.key("admissible").value(m.admissible);
  row.key("minimum_energy").value(m.minimum_energy);
  row.key("orbits").value(long(m.orbits));
  row.key("lost_orbits").value(long(m.lost));
  row.key("ftle").value(m.largest_ftle);
  row.key("chaotic_share").value(m.chaotic_share);
  row.key("hyperbolic_orbits").value(long(m.hyperbolic));
  row.key("undecided_orbits").value(long(m.undecided));
  row.key("extra_integral_range").value(m.extra_integral_range);
  // A level is failed only when every orbit on it was lost.
  row.key("failure");
  if (m.lost > 0 && m.lost == m.orbits) {
    row.begin_object();
    row.key("t").value(0.0);
    row.key("detail").value("every orbit of the level failed");
    row.end_object();
  } else {
    row.null();
  }
  row.key("cpu_seconds").value(m.cpu_seconds);
  row.end_object();
  return {row.take(), m.lost > 0 && m.lost == m.orbits};
}

}  // namespace epviz::sweep
