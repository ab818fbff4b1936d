#pragma once
// Batch steppers: many independent trajectories of one system advanced W at a
// time in structure-of-arrays lanes (batch_lanes.hpp), with the arithmetic
// compiled per instruction set (batch_kernel.hpp) and everything else here.
//
//   BatchEmbedded<Sys, W, Dop853Tableau>   DOP853 with the step-size control of
//                                          EmbeddedRk (embedded_rk.hpp)
//   BatchRk4<Sys, W>                       the classical RK4, fixed step
//
// No lockstep: every lane has its own t, step size, counters and failure, and
// each attempt of every lane is decided on its own. A lane whose trajectory
// ends or fails takes the next pending trajectory at once, so the batch never
// waits for its slowest member. A lane's results are bitwise those of the
// scalar stepper on its trajectory (the same operations in the same order),
// whatever its neighbours, W or the instruction set (docs/ensembles.md).
//
// Output: DOP853 interpolates its dense output at the requested times (the
// scalar pattern `while (s.t() < t_out) s.step(); s.dense(t_out)`); RK4 steps
// exactly to them (rk4_step_towards). A step hook (DOP853) sees every accepted
// step and may look into its dense output, e.g. to locate events in it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "numerics/batch_lanes.hpp"
#include "numerics/embedded_rk.hpp"
#include "numerics/failure.hpp"

namespace epviz::numerics {

template <int D>
struct BatchTask {
  double t0 = 0, t_end = 0;
  std::array<double, D> x0{};
  std::vector<double> out_times;  // ascending, within [t0, t_end]
  long id = 0;                    // the caller's, handed to the output check
};

template <int D>
struct BatchResult {
  std::vector<std::array<double, D>> outputs;  // at out_times (those reached when failed)
  std::array<double, D> x{};  // at t_end, or the last accepted state when failed or stopped
  double t = 0;  // t_end, or the time of the last accepted state when failed or stopped
  long steps = 0, rejected_steps = 0;
  bool stopped = false;  // a step hook ended it before t_end (t, x: that step's end)
  // Right-hand side evaluations the scalar stepper makes for this trajectory
  // (DOP853: its dense output's extra stages once per step that served an
  // output or t_end); the batch evaluates more for lanes that need none.
  long rhs_evals = 0;
  std::optional<Failure> failure;
};

// Looks at each output as it is produced (the task's id, t and state): a
// failure ends that trajectory there, without the output, as a failure the
// scalar run's consumer raises at that output time would (e.g. sim's
// MotionCheck). Called from the thread running the batch.
template <int D>
using BatchOutputCheck =
    std::function<std::optional<Failure>(long id, double t, const std::array<double, D>& x)>;

// One accepted step of a trajectory (the task's id), from (t_prev, x_prev)
// to (t, x), as a step hook sees it.
template <int D>
struct BatchStep {
  long id = 0;
  double t_prev = 0, t = 0;
  std::array<double, D> x_prev{}, x{};
};

// The dense output of the step being looked at, at a time within [t_prev, t]:
// bitwise what the scalar stepper's dense(t) gives after the same step, the
// whole state or one component (for a search that needs only one).
template <int D>
class BatchDense {
 public:
  virtual std::array<double, D> operator()(double t) const = 0;
  virtual double component(int i, double t) const = 0;

 protected:
  ~BatchDense() = default;
};

// What a step hook makes of the step it looked at.
struct BatchStepVerdict {
  bool stop = false;               // end the trajectory at this step's end
  std::optional<Failure> failure;  // end it here, failed
};

// Sees every accepted step (after the step's outputs): `wants_dense` says
// whether this step's dense output is needed, and for the steps that need it
// `look` is handed the step and its dense output. The dense coefficients of
// all lanes are computed once per attempt, and only when some lane needs them
// (an output, t_end or the hook), so a hook that asks on few steps costs
// little. Both are called from the thread running the batch, with the task's
// id in the step.
template <int D>
struct BatchStepHook {
  std::function<bool(const BatchStep<D>& step)> wants_dense;
  std::function<BatchStepVerdict(const BatchStep<D>& step, const BatchDense<D>& dense)> look;
  explicit operator bool() const { return bool(wants_dense); }
};

// Told, with the task's id, when a trajectory takes a lane and when it ends
// (reached t_end, failed or stopped; its result complete), from the thread running the
// batch: so that a caller can use each result as soon as it is there.
template <int D>
struct BatchEvents {
  std::function<void(long id)> started;
  std::function<void(long id, const BatchResult<D>& result)> ended;
};

// Throws std::invalid_argument naming the first task whose times are not
// finite, whose t_end < t0 or whose output times leave [t0, t_end] or descend.
template <int D>
void check_batch_tasks(const std::vector<BatchTask<D>>& tasks) {
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    const auto& task = tasks[i];
    const auto bad = [&](const char* what) {
      throw std::invalid_argument("batch task " + std::to_string(i) + ": " + what);
    };
    if (!std::isfinite(task.t0) || !std::isfinite(task.t_end) || task.t_end < task.t0)
      bad("t0 and t_end must be finite with t_end >= t0");
    double last = task.t0;
    for (double t : task.out_times) {
      if (!(t >= last && t <= task.t_end)) bad("output times must ascend within [t0, t_end]");
      last = t;
    }
  }
}

struct BatchRk4Options {
  double h = 0.01;               // step size (the last step before an output time is shorter)
  long max_steps = 100'000'000;  // per trajectory
};

// The RK4 step from t towards target with step size h: h, or the rest when it
// is at most h (up to 1e-9 h, so that round-off leaves no sliver of a step).
struct Rk4Step {
  double h;
  bool lands;  // the step ends exactly at target
};
inline Rk4Step rk4_step_towards(double t, double target, double h) {
  const double rest = target - t;
  if (rest <= h * (1.0 + 1e-9)) return {rest, true};
  return {h, false};
}

namespace batch {

// The trajectories not yet started and the results of all.
template <int D>
class TaskQueue {
 public:
  explicit TaskQueue(const std::vector<BatchTask<D>>& tasks) : tasks_(tasks) {
    check_batch_tasks(tasks);
    results_.resize(tasks.size());
    for (std::size_t i = 0; i < tasks.size(); ++i)
      results_[i].outputs.reserve(tasks[i].out_times.size());
  }
  // The index of the next trajectory, or -1 when none is left.
  long take() { return next_ < tasks_.size() ? long(next_++) : -1; }
  long size() const { return long(tasks_.size()); }
  const BatchTask<D>& task(long i) const { return tasks_[std::size_t(i)]; }
  BatchResult<D>& result(long i) { return results_[std::size_t(i)]; }
  std::vector<BatchResult<D>> release() { return std::move(results_); }

 private:
  const std::vector<BatchTask<D>>& tasks_;
  std::vector<BatchResult<D>> results_;
  std::size_t next_ = 0;
};

[[gnu::noinline]] inline std::string format_detail(const char* f, double v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// Readies every busy lane for an attempt (prepare(l)), refilling with load(l)
// the lanes whose trajectory ends or fails on the way; false when all are idle.
template <int W, class Prepare, class Load>
bool ready_lanes(const long (&task)[W], Prepare&& prepare, Load&& load) {
  bool any = false;
  for (int l = 0; l < W; ++l) {
    while (task[l] >= 0 && !prepare(l)) load(l);
    any = any || task[l] >= 0;
  }
  return any;
}

template <int D, int W>
bool lane_finite(const double (&x)[D][W], int l) {
  for (int i = 0; i < D; ++i)
    if (!std::isfinite(x[i][l])) return false;
  return true;
}

template <int D, int W>
void copy_lane(double (&to)[D][W], const double (&from)[D][W], int l) {
  for (int i = 0; i < D; ++i) to[i][l] = from[i][l];
}

template <int D, int W>
std::array<double, D> lane(const double (&x)[D][W], int l) {
  std::array<double, D> a;
  for (int i = 0; i < D; ++i) a[std::size_t(i)] = x[i][l];
  return a;
}

}  // namespace batch

template <BatchSystem Sys, int W, class Tableau>
class BatchEmbedded {
 public:
  static constexpr int D = Sys::dim;
  static constexpr const char* name = Tableau::name;
  using Kernels = EmbeddedKernels<Sys, W, Tableau>;

  // Throws std::invalid_argument for the options EmbeddedRk refuses.
  BatchEmbedded(Sys sys, const Kernels& kernels, AdaptiveOptions opts = {},
                BatchOutputCheck<D> check = {}, BatchEvents<D> events = {},
                BatchStepHook<D> hook = {})
      : sys_(std::move(sys)),
        kernels_(kernels),
        opts_(opts),
        check_(std::move(check)),
        events_(std::move(events)),
        hook_(std::move(hook)) {
    if (hook_ && !hook_.look)
      throw std::invalid_argument("batch step hook: wants_dense without look");
    EmbeddedRk<Probe, Tableau> validate(Probe{}, opts_);  // the very checks of the scalar stepper
    fac_min_ = opts_.fac_min < 0 ? Tableau::default_fac_min : opts_.fac_min;
    fac_max_ = opts_.fac_max < 0 ? Tableau::default_fac_max : opts_.fac_max;
    beta_ = opts_.beta < 0 ? Tableau::default_beta : opts_.beta;
    expo_ = Tableau::error_exponent - Tableau::beta_coupling * beta_;
  }

  std::vector<BatchResult<D>> run(const std::vector<BatchTask<D>>& tasks);

 private:
  using Lanes = EmbeddedLanes<D, W, Tableau>;
  static constexpr int S = Tableau::stages;
  static constexpr int M = Lanes::M;
  static constexpr int N = Lanes::N;
  static constexpr bool kErrorNeedsFsal = error_needs_fsal_v<Tableau>;
  static constexpr double kLogErrFloor = -9.210340371976182;  // as EmbeddedRk's

  // A one-dimensional system for the option checks of EmbeddedRk.
  struct Probe {
    static constexpr int dim = 1;
    using State = Vec<1>;
    void rhs(double, const State&, State& dx) const { dx[0] = 0; }
  };

  // A trajectory's last step and its bookkeeping for the output: in a lane
  // (L_), or in a slot of the steps whose dense output waits (pending_).
  struct Slot {
    Lanes* L;
    int l;
    long task;
    std::size_t* next_out;
    bool stepped;
    bool* dense_counted;
  };
  Slot lane(int l) {
    return {L_.get(), l, task_[l], &next_out_[l], stepped_[l], &dense_counted_[l]};
  }

  void load(int l);
  bool start(int l);  // false when the trajectory ended or failed at its start
  bool prepare(int l);
  bool decide(int l);                // true when accepted
  int start_slot(long task);         // where the task's k0 and h0 are in starts_
  bool emit_outputs(const Slot& s);  // false when the output check failed the trajectory
  bool hook_asks(int l);             // fills step_[l]; whether the hook wants its dense output
  bool hook_looks(int l);            // false when the hook ended the trajectory
  void defer(int l);
  void flush_pending();
  std::array<double, D> dense_used(const Slot& s, double t);
  void count_dense(const Slot& s);
  void finish(const Slot& s, std::optional<Failure> failure);
  void fail(int l, FailureKind kind, std::string detail) {
    finish(lane(l), Failure{L_->t[l], name, kind, std::move(detail)});
  }
  static double dense(const Slot& s, int i, double u) {  // u: (t - t_prev) / h_last
    const double u1 = 1.0 - u;
    const auto& c = s.L->cont;
    double r = c[M - 1][i][s.l];
    for (int j = M - 2; j >= 0; --j) r = c[j][i][s.l] + ((j % 2 == 0) ? u : u1) * r;
    return r;
  }
  static double dense_position(const Slot& s, double t) {
    return (t - s.L->t_prev[s.l]) / s.L->h_last[s.l];
  }
  static std::array<double, D> dense(const Slot& s, double t) {
    const double u = dense_position(s, t);
    std::array<double, D> x;
    for (int i = 0; i < D; ++i) x[std::size_t(i)] = dense(s, i, u);
    return x;
  }
  // Lane l's dense output, for a step hook (counted as used, as dense_used).
  class LaneDense final : public BatchDense<D> {
   public:
    LaneDense(BatchEmbedded& b, const Slot& s) : b_(b), s_(s) {}
    std::array<double, D> operator()(double t) const override { return b_.dense_used(s_, t); }
    double component(int i, double t) const override {
      b_.count_dense(s_);
      return dense(s_, i, dense_position(s_, t));
    }

   private:
    BatchEmbedded& b_;
    Slot s_;
  };
  // err^-expo of lane l's attempt (EmbeddedRk's power of the error).
  double err_power(int l) const {
    if (expo_ == 0.125) return L_->err_root8[l];
    return std::exp(-expo_ * std::log(L_->err[l]));
  }

  Sys sys_;
  Kernels kernels_;
  AdaptiveOptions opts_;
  BatchOutputCheck<D> check_;
  BatchEvents<D> events_;
  BatchStepHook<D> hook_;
  double fac_min_, fac_max_, beta_, expo_;

  std::unique_ptr<Lanes> L_;
  std::unique_ptr<batch::TaskQueue<D>> queue_;
  // Per lane: the trajectory (-1: idle), its next output, and the controller's state.
  long task_[W];
  std::size_t next_out_[W];
  double h_next_[W], log_err_old_[W];
  long attempts_[W];
  int consecutive_rejects_[W], nonfinite_trials_[W];
  bool last_rejected_[W], accepted_[W], stepped_[W];
  bool hook_dense_[W];     // the hook asked for this step's dense output
  BatchStep<D> step_[W];   // the step the hook is shown
  bool dense_counted_[W];  // this step's dense output evaluations are counted
  bool deferred_[W];       // the lane's trajectory ended; its last step waits in pending_

  // Steps that end their trajectories and need their dense output for nothing
  // else: their lanes take new trajectories at once, and their dense outputs
  // are computed W at a time (the kernel's cost is the same for one lane or W).
  std::unique_ptr<Lanes> pending_;
  int pending_count_ = 0;
  long pending_task_[W];
  std::size_t pending_next_out_[W];
  bool pending_dense_counted_[W];

  std::unique_ptr<typename Kernels::Starts> starts_;
  long start_first_ = 0;  // the task in starts_' first slot
};

template <BatchSystem Sys, int W, class Tableau>
auto BatchEmbedded<Sys, W, Tableau>::run(const std::vector<BatchTask<D>>& tasks)
    -> std::vector<BatchResult<D>> {
  queue_ = std::make_unique<batch::TaskQueue<D>>(tasks);
  L_ = std::make_unique<Lanes>();
  pending_ = std::make_unique<Lanes>();
  pending_count_ = 0;
  starts_ = std::make_unique<typename Kernels::Starts>();
  starts_->atol = opts_.atol;
  starts_->rtol = opts_.rtol;
  starts_->h_max = opts_.h_max;
  start_first_ = -W;
  L_->atol = opts_.atol;
  L_->rtol = opts_.rtol;
  for (int l = 0; l < W; ++l) load(l);
  const auto prepare_lane = [this](int l) { return prepare(l); };
  const auto load_lane = [this](int l) { load(l); };
  while (batch::ready_lanes(task_, prepare_lane, load_lane)) {
    kernels_.attempt(*L_, sys_);
    // Each lane decides on its own; what is done to the accepted lanes' state
    // is done to all of them at once in the kernels (commit, dense, fsal).
    for (int l = 0; l < W; ++l) {
      accepted_[l] = task_[l] >= 0 && decide(l);
      L_->accept[l] = accepted_[l] ? ~0LL : 0LL;
    }
    kernels_.commit(*L_);
    // The dense output is computed now when a trajectory goes on after an
    // output or a look of the hook; steps that only end their trajectories
    // wait in pending_ unless it is computed anyway.
    bool need_dense = false, ending = false;
    for (int l = 0; l < W; ++l) {
      deferred_[l] = false;
      if (!accepted_[l]) continue;
      const auto& task = queue_->task(task_[l]);
      hook_dense_[l] = hook_ && hook_asks(l);
      const bool ends = L_->t[l] >= task.t_end;
      ending = ending || ends;
      need_dense = need_dense || hook_dense_[l] ||
                   (!ends && next_out_[l] < task.out_times.size() &&
                    task.out_times[next_out_[l]] <= L_->t[l]);
    }
    if (need_dense) {
      kernels_.dense(*L_, sys_);
    } else if (ending) {
      for (int l = 0; l < W; ++l)
        if (accepted_[l] && L_->t[l] >= queue_->task(task_[l]).t_end) defer(l);
    }
    kernels_.fsal(*L_);
    for (int l = 0; l < W; ++l) {
      if (!accepted_[l]) continue;
      if (deferred_[l] || !emit_outputs(lane(l)) || (hook_dense_[l] && !hook_looks(l))) {
        load(l);
      } else if (L_->t[l] >= queue_->task(task_[l]).t_end) {
        finish(lane(l), std::nullopt);
        load(l);
      }
    }
  }
  flush_pending();
  pending_.reset();
  starts_.reset();
  L_.reset();
  auto results = queue_->release();
  queue_.reset();
  return results;
}

template <BatchSystem Sys, int W, class Tableau>
void BatchEmbedded<Sys, W, Tableau>::load(int l) {
  for (;;) {
    task_[l] = queue_->take();
    if (task_[l] < 0) {
      // Idle: harmless numbers for the kernels to chew on.
      for (int i = 0; i < D; ++i) L_->x[i][l] = L_->k[0][i][l] = 0.0;
      L_->t[l] = L_->h[l] = 0.0;
      return;
    }
    if (start(l)) return;
  }
}

template <BatchSystem Sys, int W, class Tableau>
bool BatchEmbedded<Sys, W, Tableau>::start(int l) {
  const auto& task = queue_->task(task_[l]);
  if (events_.started) events_.started(task.id);
  L_->t[l] = L_->t_prev[l] = task.t0;
  for (int i = 0; i < D; ++i) L_->x[i][l] = L_->x_prev[i][l] = task.x0[std::size_t(i)];
  step_[l].id = task.id;
  step_[l].t = task.t0;
  step_[l].x = task.x0;  // the first step's start
  h_next_[l] = opts_.h_init > 0 ? std::min(opts_.h_init, opts_.h_max) : 0.0;
  log_err_old_[l] = kLogErrFloor;
  attempts_[l] = 0;
  consecutive_rejects_[l] = nonfinite_trials_[l] = 0;
  last_rejected_[l] = false;
  stepped_[l] = false;
  next_out_[l] = 0;
  if (!emit_outputs(lane(l))) return false;  // those at t0: x0, as EmbeddedRk::dense before a step
  if (task.t_end <= task.t0) {
    finish(lane(l), std::nullopt);
    return false;
  }
  const int j = start_slot(task_[l]);
  for (int i = 0; i < D; ++i) L_->k[0][i][l] = starts_->k0[i][j];
  ++queue_->result(task_[l]).rhs_evals;
  if (!batch::lane_finite(L_->k[0], l) || !batch::lane_finite(L_->x, l)) {
    fail(l, FailureKind::non_finite, "state or derivative not finite (NaN or Inf)");
    return false;
  }
  if (h_next_[l] <= 0.0) {
    h_next_[l] = starts_->h0[j];  // as EmbeddedRk::initial_step, with its evaluation
    ++queue_->result(task_[l]).rhs_evals;
  }
  return true;
}

// The slot of starts_ that holds the task's first derivative and initial step:
// the tasks are taken in order, so a group of the next W is computed at once
// when the task is not in the last.
template <BatchSystem Sys, int W, class Tableau>
int BatchEmbedded<Sys, W, Tableau>::start_slot(long task) {
  if (task >= start_first_ && task < start_first_ + W) return int(task - start_first_);
  start_first_ = task;
  auto& S0 = *starts_;
  for (int j = 0; j < W; ++j) {
    const long i = task + j;
    const bool real = i < queue_->size();
    for (int c = 0; c < D; ++c) S0.x[c][j] = real ? queue_->task(i).x0[std::size_t(c)] : 0.0;
    S0.t[j] = real ? queue_->task(i).t0 : 0.0;
  }
  kernels_.start(S0, sys_);
  return 0;
}

// The checks at the top of EmbeddedRk::step's loop; sets the trial step size.
template <BatchSystem Sys, int W, class Tableau>
bool BatchEmbedded<Sys, W, Tableau>::prepare(int l) {
  const double h = std::min(h_next_[l], opts_.h_max);
  if (attempts_[l] >= opts_.max_steps) {
    fail(l, FailureKind::step_budget,
         "step budget of " + std::to_string(opts_.max_steps) + " steps exhausted");
    return false;
  }
  if (!(h >= 16.0 * std::numeric_limits<double>::epsilon() * std::abs(L_->t[l])) || h <= 0.0) {
    fail(l, FailureKind::step_underflow,
         batch::format_detail("step size %.3g below the round-off limit", h));
    return false;
  }
  ++attempts_[l];
  queue_->result(task_[l]).rhs_evals += kErrorNeedsFsal ? Tableau::stages : Tableau::stages - 1;
  L_->h[l] = h;
  return true;
}

// The rest of EmbeddedRk::step's loop, for lane l after an attempt.
template <BatchSystem Sys, int W, class Tableau>
bool BatchEmbedded<Sys, W, Tableau>::decide(int l) {
  auto& result = queue_->result(task_[l]);
  const double h = L_->h[l], err = L_->err[l];
  const bool finite = L_->trial_finite[l] != 0;
  if (finite && err <= 1.0) {
    double fac;
    if (beta_ == 0.0) {
      fac = opts_.safety * err_power(l);
    } else {
      const double log_err = std::log(err);
      fac = opts_.safety * std::exp(beta_ * log_err_old_[l] - expo_ * log_err);
      log_err_old_[l] = std::max(log_err, kLogErrFloor);
    }
    fac = std::clamp(fac, fac_min_, fac_max_);
    if (last_rejected_[l]) fac = std::min(fac, 1.0);
    h_next_[l] = h * fac;  // the state moves on in the commit kernel
    last_rejected_[l] = false;
    consecutive_rejects_[l] = nonfinite_trials_[l] = 0;
    stepped_[l] = true;
    dense_counted_[l] = false;
    ++result.steps;
    if (!kErrorNeedsFsal) ++result.rhs_evals;
    return true;
  }
  ++result.rejected_steps;
  last_rejected_[l] = true;
  double fac = fac_min_;
  if (finite) {
    fac = std::max(fac_min_, opts_.safety * err_power(l));
  } else {
    ++nonfinite_trials_[l];
  }
  h_next_[l] = h * fac;
  if (++consecutive_rejects_[l] > opts_.max_consecutive_rejects) {
    if (nonfinite_trials_[l] > 0)
      fail(
          l, FailureKind::non_finite,
          batch::format_detail("trial states not finite (NaN or Inf) even with step size %.3g", h));
    else
      fail(l, FailureKind::rejections,
           std::to_string(consecutive_rejects_[l]) +
               batch::format_detail(" consecutive rejected steps (last step size %.3g)", h));
    load(l);
  }
  return false;
}

// The state at t on the slot's last step (its dense output), counting the
// evaluations of the continuous extension once per step, as EmbeddedRk's
// lazy dense output does; x itself before the first step.
template <BatchSystem Sys, int W, class Tableau>
auto BatchEmbedded<Sys, W, Tableau>::dense_used(const Slot& s, double t) -> std::array<double, D> {
  if (!s.stepped) return batch::lane(s.L->x, s.l);
  count_dense(s);
  return dense(s, t);
}

template <BatchSystem Sys, int W, class Tableau>
void BatchEmbedded<Sys, W, Tableau>::count_dense(const Slot& s) {
  if (*s.dense_counted) return;
  queue_->result(s.task).rhs_evals += N - Tableau::stages - 1;
  *s.dense_counted = true;
}

template <BatchSystem Sys, int W, class Tableau>
bool BatchEmbedded<Sys, W, Tableau>::emit_outputs(const Slot& s) {
  const auto& task = queue_->task(s.task);
  auto& result = queue_->result(s.task);
  for (std::size_t& next = *s.next_out; next < task.out_times.size(); ++next) {
    const double t = task.out_times[next];
    if (!(t <= s.L->t[s.l])) break;
    const std::array<double, D> x = dense_used(s, t);
    if (check_) {
      if (auto failure = check_(task.id, t, x)) {
        finish(s, std::move(*failure));
        return false;
      }
    }
    result.outputs.push_back(x);
  }
  return true;
}

// Lane l's last step, which ends its trajectory, to a slot of pending_ (the
// dense output reads x_prev, x, k[0 .. S], t_prev and h_last).
template <BatchSystem Sys, int W, class Tableau>
void BatchEmbedded<Sys, W, Tableau>::defer(int l) {
  if (pending_count_ == W) flush_pending();
  const int j = pending_count_++;
  Lanes& P = *pending_;
  for (int i = 0; i < D; ++i) {
    P.x_prev[i][j] = L_->x_prev[i][l];
    P.x[i][j] = L_->x[i][l];
    for (int r = 0; r <= S; ++r) P.k[r][i][j] = L_->k[r][i][l];
  }
  P.t[j] = L_->t[l];
  P.t_prev[j] = L_->t_prev[l];
  P.h_last[j] = L_->h_last[l];
  pending_task_[j] = task_[l];
  pending_next_out_[j] = next_out_[l];
  pending_dense_counted_[j] = dense_counted_[l];
  deferred_[l] = true;
}

// The dense outputs of the pending steps, then their trajectories' outputs
// and ends.
template <BatchSystem Sys, int W, class Tableau>
void BatchEmbedded<Sys, W, Tableau>::flush_pending() {
  if (pending_count_ == 0) return;
  kernels_.dense(*pending_, sys_);
  for (int j = 0; j < pending_count_; ++j) {
    const Slot s{pending_.get(),        j,    pending_task_[j],
                 &pending_next_out_[j], true, &pending_dense_counted_[j]};
    if (emit_outputs(s)) finish(s, std::nullopt);
  }
  pending_count_ = 0;
}

template <BatchSystem Sys, int W, class Tableau>
bool BatchEmbedded<Sys, W, Tableau>::hook_asks(int l) {
  // The step starts where the lane's last one ended (or at the start).
  BatchStep<D>& step = step_[l];
  step.t_prev = step.t;
  step.x_prev = step.x;
  step.t = L_->t[l];
  step.x = batch::lane(L_->x, l);
  return hook_.wants_dense(step);
}

template <BatchSystem Sys, int W, class Tableau>
bool BatchEmbedded<Sys, W, Tableau>::hook_looks(int l) {
  BatchStepVerdict verdict = hook_.look(step_[l], LaneDense(*this, lane(l)));
  if (!verdict.failure && !verdict.stop) return true;
  if (!verdict.failure) queue_->result(task_[l]).stopped = true;
  finish(lane(l), std::move(verdict.failure));
  return false;
}

template <BatchSystem Sys, int W, class Tableau>
void BatchEmbedded<Sys, W, Tableau>::finish(const Slot& s, std::optional<Failure> failure) {
  const auto& task = queue_->task(s.task);
  auto& result = queue_->result(s.task);
  if (failure || result.stopped) {
    result.t = s.L->t[s.l];
    result.x = batch::lane(s.L->x, s.l);
  } else {
    result.t = task.t_end;
    result.x = dense_used(s, task.t_end);
  }
  result.failure = std::move(failure);
  if (events_.ended) events_.ended(task.id, result);
}

}  // namespace epviz::numerics
