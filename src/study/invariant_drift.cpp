#include "study/invariant_drift.hpp"

#include <algorithm>
#include <cmath>

#include "sim/drift.hpp"
#include "study/timed_run.hpp"

namespace epviz::study {

std::vector<DriftRow> drift_study(const StudyOptions& o) {
  std::vector<DriftRow> rows;
  const double t_end = o.quick ? 1e3 : 1e5;
  const int samples = 200;
  // Budget: evaluations (rhs + exact sub-flows) per time unit, the same for every method.
  const double budget = 200.0;
  for (const auto c : {physics::Case::kovalevskaya, physics::Case::goryachev_chaplygin}) {
    const auto studied = cases_of(o);
    if (std::find(studied.begin(), studied.end(), c) == studied.end()) continue;
    const auto& p = physics::preset(c);
    for (const auto m : methods_of(o)) {
      if (sim::incompatibility(m, sim::Formulation::direct)) continue;
      tell(o, "drift: " + p.name + " " + std::string(sim::name(m)));
      // Calibrate on a short run: the accuracy setting whose cost per time unit
      // is the largest within the budget.
      const double t_cal = 50.0;
      auto spec = sim::preset_run(c, m, sim::Formulation::direct, t_cal, 1);
      if (sim::is_adaptive(m)) {
        double chosen = 1e-3;
        for (double tol = 1e-3; tol >= 1e-14; tol /= std::sqrt(10.0)) {
          spec.tol = tol;
          const auto r = sim::simulate(spec);
          if (double(r.stats.rhs_evals + r.stats.flow_evals) / t_cal > budget) break;
          chosen = tol;
        }
        spec.tol = chosen;
      } else {
        spec.step = 0.01;
        const auto r = sim::simulate(spec);
        const double per_step =
            double(r.stats.rhs_evals + r.stats.flow_evals) / double(std::max(1L, r.stats.steps));
        spec.step = per_step / budget;
      }
      spec.t_end = t_end;
      spec.samples = samples;
      const auto t = timed_run(spec, 1);
      DriftRow row{run_record(spec, t)};
      row.budget_evals_per_time = budget;
      const sim::InvariantMonitor monitor(spec.body, c, spec.initial);
      const auto d = monitor.max_relative_drift(t.result.samples);
      row.drift_gamma_norm2 = d.gamma_norm2;
      row.drift_C0 = d.area;
      row.drift_C1 = d.energy;
      row.drift_extra = d.extra.value_or(kNaN);
      for (const auto& s : t.result.samples) {
        const auto rd = monitor.relative_drift(monitor.at(s));
        row.series_t.push_back(s.t);
        row.series_drift_C1.push_back(rd.energy);
        row.series_drift_extra.push_back(rd.extra.value_or(kNaN));
        row.series_drift_gamma_norm2.push_back(rd.gamma_norm2);
      }
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace epviz::study
