#include "sim/run_options.hpp"

namespace epviz::sim {

double adaptive_tol(const RunSpec& run) {
  return is_adaptive(run.method) ? run.tol : RunSpec{}.tol;
}

numerics::AdaptiveOptions adaptive_options(const RunSpec& run) {
  numerics::AdaptiveOptions opts;
  opts.rtol = opts.atol = adaptive_tol(run);
  opts.max_steps = run.max_steps;
  return opts;
}

bool batchable(const RunSpec& run) {
  return run.formulation == Formulation::direct && run.method == Method::dop853;
}

sim::DirectBatchSettings dop853_batch_settings(const RunSpec& run) {
  sim::DirectBatchSettings s;
  s.method = sim::BatchMethod::dop853;
  s.adaptive = adaptive_options(run);
  return s;
}

bool share_a_batch(const RunSpec& a, const RunSpec& b) {
  return adaptive_tol(a) == adaptive_tol(b) && a.max_steps == b.max_steps &&
         a.body.inertia == b.body.inertia && a.body.com == b.body.com &&
         a.body.weight == b.body.weight;
}

}  // namespace epviz::sim
