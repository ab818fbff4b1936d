#include "study/invariant_cost.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "sim/drift.hpp"
#include "study/reference.hpp"
#include "study/timed_run.hpp"

namespace epviz::study {

std::vector<InvariantCostRow> invariant_cost_study(const StudyOptions& o, double t_end,
                                                   double target) {
  std::vector<InvariantCostRow> rows;
  const auto c = physics::Case::kovalevskaya;
  const auto& p = physics::preset(c);
  if (t_end <= 0.0) t_end = o.quick ? 1e3 : 1e4;
  const int samples = 1000;  // the drifts are the largest over these output times
  const double period = fastest_period(p.initial);
  // The ladder stops before a run would exceed this many evaluations per time
  // unit (about 1 s of CPU for the costliest method at t_end = 1e4).
  const double cap_per_time = 2000.0;
  for (const auto m : methods_of(o)) {
    if (sim::incompatibility(m, sim::Formulation::direct)) continue;
    tell(o, "invariant cost: " + p.name + " " + std::string(sim::name(m)));
    const bool adaptive = sim::is_adaptive(m);
    auto spec = sim::preset_run(c, m, sim::Formulation::direct, t_end, samples);
    sim::RunSpec last_spec = spec;
    std::optional<TimedRun> last;
    sim::Drifts last_drift;
    bool reached = false;
    for (int k = 0; k < 40 && !reached; ++k) {
      if (adaptive) {
        spec.tol = 1e-4 * std::pow(10.0, -0.5 * k);  // 1e-4, 3.2e-5, ...
        if (spec.tol < 1e-15) break;
      } else {
        spec.step = period / 4.0 * std::pow(2.0, -0.5 * k);  // period/4, period/5.7, ...
      }
      // Predict the cost from the previous rung (fixed steps: proportional to
      // 1/step; tolerances: at least as costly): stop before the cap.
      if (last && !adaptive && double(last->cost) * std::sqrt(2.0) > cap_per_time * t_end) break;
      if (last && adaptive && double(last->cost) > cap_per_time * t_end / 1.5) break;
      const auto r = sim::simulate(spec);
      TimedRun t;
      t.result = r;
      t.cost = r.stats.rhs_evals + r.stats.flow_evals;
      if (double(t.cost) > 1.5 * cap_per_time * t_end && last)
        break;  // over the cap: keep the previous rung
      const sim::InvariantMonitor monitor(spec.body, c, spec.initial);
      sim::Drifts d;
      d.energy = d.area = d.gamma_norm2 = kNaN;
      bool ok = !r.failure && !r.samples.empty() && r.samples.back().t == t_end;
      for (const auto& smp : r.samples) ok = ok && finite(smp);
      if (ok) d = monitor.max_relative_drift(r.samples);
      const double extra = d.extra.value_or(kNaN);
      reached = ok && d.energy < target && extra < target;
      last = std::move(t);
      last_spec = spec;
      last_drift = d;
      if (reached) {
        // CPU time of the chosen run, repeated.
        auto timed = timed_run(spec, o.quick ? 1 : std::min(repeats_of(o), 3));
        last->cpu_median = timed.cpu_median;
        last->repeats = timed.repeats;
      } else {
        last->cpu_median = r.cpu_seconds;
        last->repeats = 1;
      }
    }
    if (!last) continue;
    // The row describes the chosen (reached) or the finest tried rung.
    InvariantCostRow row{run_record(last_spec, *last)};
    row.target = target;
    row.drift_C1 = last_drift.energy;
    row.drift_extra = last_drift.extra.value_or(kNaN);
    row.reached = reached;
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace epviz::study
