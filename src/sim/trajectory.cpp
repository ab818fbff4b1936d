#include "sim/trajectory.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/drift.hpp"
#include "sim/rhs_tally.hpp"
#include "sim/trajectory_start.hpp"

namespace epviz::sim {
namespace {

// Every trajectory hands out only samples that keep the motion (sim/drift.hpp):
// the first output time that does not ends the run as a numerical failure, so
// that no consumer writes or draws it.
class CheckedTrajectory final : public Trajectory {
 public:
  CheckedTrajectory(std::unique_ptr<Trajectory> inner, const RunSpec& spec)
      : Trajectory(inner->spacing()),
        inner_(std::move(inner)),
        check_(spec.body, spec.initial, spec.max_drift),
        method_(name(spec.method)) {}

  Sample initial() const override { return inner_->initial(); }
  Sample next() override {
    Sample s = next_tallied();
    if (auto f = check_.failure(s, method_)) [[unlikely]]
      throw numerics::IntegrationError(std::move(*f));
    return s;
  }
  numerics::Stats stats() const override { return inner_->stats(); }
  long chart_switches() const override { return inner_->chart_switches(); }
  double effective_step() const override { return inner_->effective_step(); }
  long interpolation_evals() const override { return inner_->interpolation_evals(); }
  void observe_steps(StepObserver observer) override { inner_->observe_steps(std::move(observer)); }
  void observe_dense_steps(DenseStepObserver observer) override {
    inner_->observe_dense_steps(std::move(observer));
  }

 private:
  // The inner run's next sample, its evaluations added to the process's
  // tally (sim/rhs_tally.hpp), a failed step's too.
  Sample next_tallied() {
    try {
      Sample s = inner_->next();
      tally();
      return s;
    } catch (...) {
      tally();
      throw;
    }
  }
  void tally() {
    const long spent = inner_->stats().rhs_evals + inner_->interpolation_evals();
    tally_rhs_evals(spent - tallied_);
    tallied_ = spent;
  }

  std::unique_ptr<Trajectory> inner_;
  MotionCheck check_;
  std::string method_;
  long tallied_ = 0;
};

std::unique_ptr<Trajectory> start_unchecked(const RunSpec& spec) {
  switch (spec.formulation) {
    case Formulation::direct: return detail::start_direct(spec);
    case Formulation::riccati: return detail::start_riccati(spec);
    case Formulation::spinor: return detail::start_spinor(spec);
  }
  throw std::invalid_argument("unknown formulation");
}

}  // namespace

std::unique_ptr<Trajectory> Trajectory::start(const RunSpec& spec) {
  if (auto why = incompatibility(spec.method, spec.formulation)) throw std::invalid_argument(*why);
  if (!(spec.t_end > 0.0) || spec.samples < 1)
    throw std::invalid_argument("t_end must be positive and samples at least 1");
  if (!(spec.max_drift > 0.0)) throw std::invalid_argument("max_drift must be positive");
  if (!is_adaptive(spec.method) && !(spec.step > 0.0 && std::isfinite(spec.step)))
    throw std::invalid_argument("step must be positive and finite");
  return std::make_unique<CheckedTrajectory>(start_unchecked(spec), spec);
}

}  // namespace epviz::sim
