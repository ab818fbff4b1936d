#include "study/timed_run.hpp"

#include "study/timing.hpp"

namespace epviz::study {

TimedRun timed_run(const sim::RunSpec& spec, int repeats) {
  TimedRun t;
  t.result = sim::simulate(spec);
  std::vector<double> cpu{t.result.cpu_seconds};
  const int n = repeats_after_first(t.result.cpu_seconds, repeats);
  for (int i = 1; i < n; ++i) cpu.push_back(sim::simulate(spec).cpu_seconds);
  t.cpu_median = median(cpu);
  t.repeats = int(cpu.size());
  t.cost = t.result.stats.rhs_evals + t.result.stats.flow_evals;
  return t;
}

RunRecord run_record(const sim::RunSpec& spec, const TimedRun& t) {
  RunRecord r;
  r.case_name = spec.case_id == physics::Case::custom ? std::string("custom")
                                                      : physics::case_name(spec.case_id);
  r.formulation = std::string(sim::name(spec.formulation));
  r.method = std::string(sim::name(spec.method));
  r.adaptive = sim::is_adaptive(spec.method);
  r.tol = r.adaptive ? spec.tol : kNaN;
  r.step = r.adaptive ? kNaN : t.result.effective_step;
  r.t_end = spec.t_end;
  r.steps = t.result.stats.steps;
  r.rhs_evals = t.result.stats.rhs_evals;
  r.flow_evals = t.result.stats.flow_evals;
  r.cpu_ms = 1e3 * t.cpu_median;
  r.repeats = t.repeats;
  if (const auto& f = t.result.failure) {
    r.ok = false;
    r.failure_t = f->t;
    r.failure_reason = f->detail;
  }
  return r;
}

bool finite(const sim::Sample& s) { return s.omega.allFinite() && s.gamma.allFinite(); }

}  // namespace epviz::study
