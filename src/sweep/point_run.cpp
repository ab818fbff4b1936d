#include "sweep/point_run.hpp"

#include <cmath>
#include <cstdio>

#include "sim/drift.hpp"
#include "sim/trajectory.hpp"

namespace epviz::sweep {
namespace {

using Row = nlohmann::ordered_json;

Row number_or_null(double x) { return std::isfinite(x) ? Row(x) : Row(nullptr); }

Row vec(const Eigen::Vector3d& v) { return Row::array({v[0], v[1], v[2]}); }

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

using State = Eigen::Matrix<double, 6, 1>;

constexpr int kKeptSamples = 100'000;

State state_of(const sim::Sample& s) {
  State x;
  x << s.omega, s.gamma;
  return x;
}

// The state after `window` from `x`, by the run's own method and accuracy.
std::optional<State> advance(const sim::RunSpec& run, const State& x, double window) {
  sim::RunSpec one = run;
  one.initial.omega = x.head<3>();
  one.initial.gamma = x.tail<3>();
  one.t_end = window;
  one.samples = 1;
  try {
    auto t = sim::Trajectory::start(one);
    return state_of(t->next());
  } catch (const numerics::IntegrationError&) {
    return std::nullopt;
  }
}

}  // namespace

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

std::optional<double> finite_time_lyapunov(const sim::RunSpec& run, const FtleSettings& settings) {
  const double window = settings.window > 0.0 ? settings.window : run.t_end / run.samples;
  const long windows = std::max(1L, std::lround(run.t_end / window));
  State a;
  a << run.initial.omega, run.initial.gamma;
  // The first offset: along (1,1,1) in omega and in the plane tangent to the
  // sphere |gamma| = 1 in gamma, so that the neighbour is a physical state.
  State u = State::Ones();
  const Eigen::Vector3d g = run.initial.gamma.normalized();
  u.tail<3>() -= g * g.dot(u.tail<3>());
  u.normalize();
  State b = a + settings.separation * u;
  double sum = 0.0;
  for (long k = 0; k < windows; ++k) {
    const auto na = advance(run, a, window);
    const auto nb = advance(run, b, window);
    if (!na || !nb) return std::nullopt;
    a = *na;
    const State d = *nb - a;
    const double dist = d.norm();
    if (!(dist > 0.0) || !std::isfinite(dist)) return std::nullopt;
    sum += std::log(dist / settings.separation);
    b = a + d * (settings.separation / dist);
  }
  return sum / (double(windows) * window);
}

nlohmann::ordered_json run_point(const PointFields& point, const sim::RunSpec& run,
                                 const std::string& sweep_hash, bool reference,
                                 const std::optional<FtleSettings>& ftle, ReferenceCache* cache) {
  const sim::InvariantMonitor monitor(run.body, run.case_id, run.initial);
  sim::Drifts drift = monitor.no_drift();
  std::vector<sim::Sample> kept;
  sim::Sample last;
  bool any = false;
  auto fold = [&](const sim::Sample& s) {
    monitor.worsen(drift, s);
    last = s;
    any = true;
  };
  // The streamed run reads the CPU clock around every sample (a system call
  // each, several times a short run's integration), so runs of a modest
  // number of samples keep them and fold them in afterwards; only very long
  // sample lists are streamed, to keep memory flat.
  sim::RunResult result;
  if (run.samples <= kKeptSamples) {
    result = sim::simulate(run);
    for (const auto& s : result.samples) fold(s);
    if (reference) kept = std::move(result.samples);
  } else {
    result = sim::simulate(run, [&](const sim::Sample& s) {
      fold(s);
      if (reference) kept.push_back(s);
    });
  }

  Row row;
  row["index"] = point.index;
  row["sweep"] = sweep_hash;
  row["axes"] = point.axis_values;
  if (!point.ignored.empty()) row["ignored"] = point.ignored;
  row["case"] = physics::case_name(run.case_id);
  row["formulation"] = std::string(sim::name(run.formulation));
  row["method"] = std::string(sim::name(run.method));
  if (sim::is_adaptive(run.method)) {
    row["tol"] = run.tol;
  } else {
    row["step"] = run.step;
    row["effective_step"] = result.effective_step;
  }
  row["initial"] = {{"omega", vec(run.initial.omega)}, {"gamma", vec(run.initial.gamma)}};
  row["energy"] =
      physics::invariants(run.body, physics::Case::custom, run.initial.omega, run.initial.gamma)
          .energy;
  row["t_end"] = run.t_end;
  if (result.failure) {
    row["failure_kind"] = std::string(numerics::name(result.failure->kind));
    row["failure"] = {{"t", result.failure->t}, {"detail", result.failure->detail}};
  } else {
    row["failure_kind"] = nullptr;
    row["failure"] = nullptr;
  }
  row["max_relative_drift"] = {
      {"gamma_norm2", number_or_null(drift.gamma_norm2)},
      {"area", number_or_null(drift.area)},
      {"energy", number_or_null(drift.energy)},
      {"extra_integral", drift.extra ? number_or_null(*drift.extra) : Row(nullptr)}};
  if (any)
    row["final"] = {{"t", last.t}, {"omega", vec(last.omega)}, {"gamma", vec(last.gamma)}};
  else
    row["final"] = nullptr;
  row["samples_written"] = result.samples_written;
  row["steps"] = result.stats.steps;
  row["rhs_evals"] = result.stats.rhs_evals;
  row["rejected_steps"] = result.stats.rejected_steps;
  row["cpu_seconds"] = result.cpu_seconds;
  if (reference) {
    ReferenceCache local;
    const auto ref = (cache ? *cache : local).get(run);
    row["reference_error"] =
        ref->empty() ? Row(nullptr) : number_or_null(max_separation(kept, *ref));
  }
  if (ftle) {
    const auto l = finite_time_lyapunov(run, *ftle);
    row["ftle"] = l ? number_or_null(*l) : Row(nullptr);
  }
  return row;
}

}  // namespace epviz::sweep
