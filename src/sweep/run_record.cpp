#include "sweep/run_record.hpp"

#include "physics/cases.hpp"

namespace epviz::sweep {

void write_run_record(io::JsonLine& j, const sim::RunSpec& spec, const sim::RunResult& r,
                      const sim::Drifts& drift) {
  j.key("case").value(physics::case_name(spec.case_id));
  j.key("formulation").value(sim::name(spec.formulation));
  j.key("method").value(sim::name(spec.method));
  if (sim::is_adaptive(spec.method)) {
    j.key("tol").value(spec.tol);
  } else {
    j.key("step").value(spec.step);
    j.key("effective_step").value(r.effective_step);
  }
  const auto& w = spec.initial.omega;
  const auto& g = spec.initial.gamma;
  j.key("initial").begin_object();
  j.key("omega").triple(w[0], w[1], w[2]);
  j.key("gamma").triple(g[0], g[1], g[2]);
  j.end_object();
  j.key("t_end").value(spec.t_end);
  j.key("failure_kind");
  if (r.failure)
    j.value(numerics::name(r.failure->kind));
  else
    j.null();
  j.key("max_relative_drift").begin_object();
  j.key("gamma_norm2").value(drift.gamma_norm2);
  j.key("area").value(drift.area);
  j.key("energy").value(drift.energy);
  j.key("extra_integral").value(drift.extra);
  j.end_object();
  j.key("samples_written").value(r.samples_written);
  j.key("steps").value(r.stats.steps);
  j.key("rhs_evals").value(r.stats.rhs_evals);
  j.key("rejected_steps").value(r.stats.rejected_steps);
  j.key("cpu_seconds").value(r.cpu_seconds);
}

}  // namespace epviz::sweep
