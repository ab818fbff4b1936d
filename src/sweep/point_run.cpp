#include "sweep/point_run.hpp"

#include <cmath>
#include <cstdio>

#include "io/json_text.hpp"
#include "sim/drift.hpp"
#include "sim/trajectory.hpp"
#include "sweep/run_record.hpp"

namespace epviz::sweep {
namespace {

std::string key_of(const sim::RunSpec& r) {
  std::string k;
  char buf[40];
  auto put = [&](double x) {
    std::snprintf(buf, sizeof buf, "%.17g,", x);
    k += buf;
  };
  for (int i = 0; i < 3; ++i) {
    put(r.body.inertia[i]);
    put(r.body.com[i]);
    put(r.initial.omega[i]);
    put(r.initial.gamma[i]);
  }
  put(r.body.weight);
  put(r.t_end);
  put(double(r.samples));
  put(r.max_drift);
  return k;
}

FtleState state_of(const sim::Sample& s) {
  FtleState x;
  x << s.omega, s.gamma;
  return x;
}

// The state after `window` from `x`, by the run's own method and accuracy.
std::optional<FtleState> advance(const sim::RunSpec& run, const FtleState& x, double window) {
  try {
    auto t = sim::Trajectory::start(window_run(run, x, window));
    return state_of(t->next());
  } catch (const numerics::IntegrationError&) {
    return std::nullopt;
  }
}

}  // namespace

sim::RunSpec window_run(const sim::RunSpec& run, const FtleState& x, double window) {
  sim::RunSpec one = run;
  one.initial.omega = x.head<3>();
  one.initial.gamma = x.tail<3>();
  one.t_end = window;
  one.samples = 1;
  return one;
}

sim::RunSpec reference_run(const sim::RunSpec& run) {
  sim::RunSpec r = run;
  r.formulation = sim::Formulation::direct;
  r.method = sim::Method::dop853;
  r.tol = 1e-13;
  r.chart_switch = true;
  return r;
}

std::shared_ptr<const std::vector<sim::Sample>> ReferenceCache::get(const sim::RunSpec& run) {
  using Ptr = std::shared_ptr<const std::vector<sim::Sample>>;
  const std::string key = key_of(run);
  std::promise<Ptr> promise;
  std::shared_future<Ptr> future;
  bool mine = false;
  {
    std::lock_guard lock(mutex_);
    auto it = runs_.find(key);
    if (it == runs_.end()) {
      future = promise.get_future().share();
      runs_.emplace(key, future);
      mine = true;
    } else {
      future = it->second;
    }
  }
  if (mine) {
    std::vector<sim::Sample> samples;
    try {
      auto result = sim::simulate(reference_run(run));
      if (!result.failure) samples = std::move(result.samples);
    } catch (const std::exception&) {
      // A reference that cannot run is one that failed: no separation.
    }
    promise.set_value(std::make_shared<const std::vector<sim::Sample>>(std::move(samples)));
  }
  return future.get();
}

double max_separation(const std::vector<sim::Sample>& a, const std::vector<sim::Sample>& b) {
  double worst = 0.0;
  const std::size_t n = std::min(a.size(), b.size());
  for (std::size_t i = 0; i < n; ++i)
    worst = std::max(worst, std::sqrt((a[i].omega - b[i].omega).squaredNorm() +
                                      (a[i].gamma - b[i].gamma).squaredNorm()));
  return worst;
}

FtleWindows::FtleWindows(const sim::RunSpec& run, const FtleSettings& settings)
    : curve_wanted_(settings.curve),
      separation_(settings.separation),
      window_(settings.window > 0.0 ? settings.window : run.t_end / run.samples),
      windows_(std::max(1L, std::lround(run.t_end / window_))) {
  a_ << run.initial.omega, run.initial.gamma;
  // The first offset: along (1,1,1) in omega and in the plane tangent to the
  // sphere |gamma| = 1 in gamma, so that the neighbour is a physical state.
  FtleState u = FtleState::Ones();
  const Eigen::Vector3d g = run.initial.gamma.normalized();
  u.tail<3>() -= g * g.dot(u.tail<3>());
  u.normalize();
  b_ = a_ + separation_ * u;
}

void FtleWindows::absorb(const std::optional<FtleState>& a, const std::optional<FtleState>& b) {
  if (done()) return;
  if (!a || !b) {
    failed_ = true;
    return;
  }
  a_ = *a;
  const FtleState d = *b - a_;
  const double dist = d.norm();
  if (!(dist > 0.0) || !std::isfinite(dist)) {
    failed_ = true;
    return;
  }
  sum_ += std::log(dist / separation_);
  b_ = a_ + d * (separation_ / dist);
  ++k_;
  // k a power of two, or the last window: evenly spaced on a log axis.
  if (curve_wanted_ && ((k_ & (k_ - 1)) == 0 || k_ == windows_)) {
    const double t = double(k_) * window_;
    curve_.push_back({t, sum_ / t});
  }
}

std::optional<double> FtleWindows::value() const {
  if (failed_ || k_ < windows_) return std::nullopt;
  return sum_ / (double(windows_) * window_);
}

namespace {

FtleWindows run_windows(const sim::RunSpec& run, const FtleSettings& settings,
                        const std::function<void(const FtleState&)>& on_window) {
  FtleWindows w(run, settings);
  while (!w.done()) {
    const auto a = advance(run, w.base(), w.window());
    const auto b = advance(run, w.neighbour(), w.window());
    w.absorb(a, b);
    if (a && on_window) on_window(*a);
  }
  return w;
}

}  // namespace

std::optional<double> finite_time_lyapunov(const sim::RunSpec& run, const FtleSettings& settings,
                                           const std::function<void(const FtleState&)>& on_window) {
  return run_windows(run, settings, on_window).value();
}

FtleResult ftle_result(const sim::RunSpec& run, const FtleSettings& settings) {
  return run_windows(run, settings, {}).result();
}

PreparedPoint prepared_point(const PointFields& fields, sim::RunSpec run) {
  PreparedPoint p{
      fields.index, io::json_text(fields.axis_values), fields.ignored, std::move(run), {}};
  if (fields.area) p.level = physics::Level{*fields.energy, *fields.area};
  return p;
}

namespace {

// Folds samples into an outcome's drift and last sample.
class Folder {
 public:
  explicit Folder(const sim::RunSpec& run) : monitor_(run.body, run.case_id, run.initial) {
    out_.drift = monitor_.no_drift();
  }
  void operator()(const sim::Sample& s) {
    monitor_.worsen(out_.drift, s);
    out_.last = s;
  }
  PointOutcome& outcome() { return out_; }

 private:
  sim::InvariantMonitor monitor_;
  PointOutcome out_;
};

}  // namespace

PointOutcome outcome_of(const sim::RunSpec& run, sim::RunResult result, bool keep_samples) {
  Folder fold(run);
  for (const auto& s : result.samples) fold(s);
  PointOutcome& out = fold.outcome();
  if (keep_samples) out.kept = std::move(result.samples);
  result.samples.clear();
  out.result = std::move(result);
  return std::move(out);
}

PointRow run_point(const PreparedPoint& point, const std::string& sweep_hash, bool reference,
                   const std::optional<FtleSettings>& ftle, ReferenceCache* cache) {
  const sim::RunSpec& run = point.run;
  // The streamed run reads the CPU clock around every sample (a system call
  // each, several times a short run's integration), so runs of a modest
  // number of samples keep them and fold them in afterwards; only very long
  // sample lists are streamed, to keep memory flat.
  PointOutcome outcome;
  if (run.samples <= kKeptSamples) {
    outcome = outcome_of(run, sim::simulate(run), reference);
  } else {
    Folder fold(run);
    std::vector<sim::Sample> kept;
    auto result = sim::simulate(run, [&](const sim::Sample& s) {
      fold(s);
      if (reference) kept.push_back(s);
    });
    outcome = std::move(fold.outcome());
    outcome.result = std::move(result);
    outcome.kept = std::move(kept);
  }
  std::optional<FtleResult> exponent;
  if (ftle) exponent = ftle_result(run, *ftle);
  return point_row(point, sweep_hash, outcome, reference, cache, exponent);
}

void begin_row(io::JsonLine& row, const PreparedPoint& point, const std::string& sweep_hash) {
  row.begin_object();
  row.key("index").value(point.index);
  row.key("sweep").value(sweep_hash);
  row.key("axes").raw(point.axes);
}

PointRow point_row(const PreparedPoint& point, const std::string& sweep_hash,
                   const PointOutcome& outcome, bool reference, ReferenceCache* cache,
                   const std::optional<FtleResult>& ftle) {
  const sim::RunSpec& run = point.run;
  const sim::RunResult& result = outcome.result;
  io::JsonLine row;
  begin_row(row, point, sweep_hash);
  if (!point.ignored.empty()) {
    row.key("ignored").begin_array();
    for (const auto& name : point.ignored) row.value(name);
    row.end_array();
  }
  row.key("energy").value(
      physics::invariants(run.body, physics::Case::custom, run.initial.omega, run.initial.gamma)
          .energy);
  write_run_record(row, run, result, outcome.drift);
  row.key("failure");
  if (result.failure) {
    row.begin_object();
    row.key("t").value(result.failure->t);
    row.key("detail").value(result.failure->detail);
    row.end_object();
  } else {
    row.null();
  }
  row.key("final");
  if (const auto& last = outcome.last) {
    row.begin_object();
    row.key("t").value(last->t);
    row.key("omega").triple(last->omega[0], last->omega[1], last->omega[2]);
    row.key("gamma").triple(last->gamma[0], last->gamma[1], last->gamma[2]);
    row.end_object();
  } else {
    row.null();
  }
  if (reference) {
    ReferenceCache local;
    const auto ref = (cache ? *cache : local).get(run);
    row.key("reference_error")
        .value(ref->empty() ? std::nullopt : std::optional(max_separation(outcome.kept, *ref)));
  }
  if (ftle) {
    row.key("ftle").value(ftle->value);
    if (!ftle->curve.empty()) {
      row.key("ftle_curve").begin_array();
      for (const auto& p : ftle->curve) {
        row.begin_array();
        row.value(p.t).value(p.lambda);
        row.end_array();
      }
      row.end_array();
    }
  }
  row.end_object();
  return {row.take(), result.failure.has_value()};
}

}  // namespace epviz::sweep
