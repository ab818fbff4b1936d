#pragma once
// The classical RK4 on W lanes at a fixed step size (see batch_driver.hpp for
// what is shared with the batch DOP853): each lane steps by h towards its next
// output time and lands on it exactly (rk4_step_towards), as a scalar Rk4
// driven by the same rule would.
#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "numerics/batch_driver.hpp"

namespace epviz::numerics {

template <BatchSystem Sys, int W>
class BatchRk4 {
 public:
  static constexpr int D = Sys::dim;
  static constexpr const char* name = "rk4";

  BatchRk4(Sys sys, const Rk4Kernel<Sys, W>& kernel, BatchRk4Options opts = {})
      : sys_(std::move(sys)), kernel_(kernel), opts_(opts) {
    if (!(opts_.h > 0 && std::isfinite(opts_.h)))
      throw std::invalid_argument("rk4: the step size must be finite and > 0");
  }

  std::vector<BatchResult<D>> run(const std::vector<BatchTask<D>>& tasks) {
    queue_ = std::make_unique<batch::TaskQueue<D>>(tasks);
    L_ = std::make_unique<Rk4Lanes<D, W>>();
    for (int l = 0; l < W; ++l) load(l);
    const auto prepare_lane = [this](int l) { return prepare(l); };
    const auto load_lane = [this](int l) { load(l); };
    while (batch::ready_lanes(task_, prepare_lane, load_lane)) {
      kernel_.step(*L_, sys_);
      for (int l = 0; l < W; ++l)
        if (task_[l] >= 0 && !advance(l)) load(l);
    }
    L_.reset();
    auto results = queue_->release();
    queue_.reset();
    return results;
  }

 private:
  const BatchTask<D>& task(int l) const { return queue_->task(task_[l]); }
  BatchResult<D>& result(int l) { return queue_->result(task_[l]); }
  double target(int l) const {
    const auto& out = task(l).out_times;
    return next_out_[l] < out.size() ? out[next_out_[l]] : task(l).t_end;
  }

  void load(int l) {
    for (;;) {
      task_[l] = queue_->take();
      if (task_[l] < 0) {
        for (int i = 0; i < D; ++i) L_->x[i][l] = 0.0;
        L_->t[l] = L_->h[l] = 0.0;
        return;
      }
      L_->t[l] = task(l).t0;
      for (int i = 0; i < D; ++i) L_->x[i][l] = task(l).x0[std::size_t(i)];
      next_out_[l] = 0;
      if (!arrived(l)) return;
    }
  }

  // Records the outputs at the lane's time; true (and the result finished)
  // when the lane has reached t_end.
  bool arrived(int l) {
    const auto& out = task(l).out_times;
    for (; next_out_[l] < out.size() && out[next_out_[l]] <= L_->t[l]; ++next_out_[l])
      result(l).outputs.push_back(batch::lane(L_->x, l));
    if (L_->t[l] < task(l).t_end) return false;
    finish(l, std::nullopt);
    return true;
  }

  bool prepare(int l) {
    if (result(l).steps >= opts_.max_steps) {
      finish(l, Failure{L_->t[l], name, FailureKind::step_budget,
                        "step budget of " + std::to_string(opts_.max_steps) + " steps exhausted"});
      return false;
    }
    const Rk4Step step = rk4_step_towards(L_->t[l], target(l), opts_.h);
    L_->h[l] = step.h;
    lands_[l] = step.lands;
    return true;
  }

  // Accepts the lane's new state; false when its trajectory ended or failed.
  bool advance(int l) {
    result(l).rhs_evals += 4;  // as Rk4::step, counted before its check
    if (!batch::lane_finite(L_->xnew, l)) {
      // As Rk4::step: the failure is dated at the end of the step, the state kept.
      finish(l, Failure{L_->t[l] + L_->h[l], name, FailureKind::non_finite,
                        "state not finite (NaN or Inf)"});
      return false;
    }
    batch::copy_lane(L_->x, L_->xnew, l);
    L_->t[l] = lands_[l] ? target(l) : L_->t[l] + L_->h[l];
    ++result(l).steps;
    return !arrived(l);
  }

  void finish(int l, std::optional<Failure> failure) {
    result(l).t = failure ? L_->t[l] : task(l).t_end;
    result(l).x = batch::lane(L_->x, l);
    result(l).failure = std::move(failure);
  }

  Sys sys_;
  Rk4Kernel<Sys, W> kernel_;
  BatchRk4Options opts_;
  std::unique_ptr<Rk4Lanes<D, W>> L_;
  std::unique_ptr<batch::TaskQueue<D>> queue_;
  long task_[W];
  std::size_t next_out_[W];
  bool lands_[W];
};

}  // namespace epviz::numerics
