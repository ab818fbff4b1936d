#pragma once
// Running one point of a sweep and describing it as a row: failure (kind and
// time) or none, the largest relative drift of every invariant, the final
// state, steps, evaluations and CPU time, the same numbers `epviz simulate`
// reports for the same run; optionally the separation from a reference run
// and a finite-time Lyapunov exponent. Safe to call from several threads.
#include <functional>
#include <future>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "io/json_line.hpp"
#include "physics/level_set.hpp"
#include "sim/drift.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"
#include "sweep/sweep_point.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {

// The reference of a run: the same body, initial state, end time and output
// times, integrated by dop853 at tolerance 1e-13 in the direct formulation.
// Points that share these (every method and step at one energy) share one
// reference run, computed once by whichever thread asks first.
class ReferenceCache {
 public:
  // The reference's samples; empty when the reference itself failed.
  std::shared_ptr<const std::vector<sim::Sample>> get(const sim::RunSpec& run);

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_future<std::shared_ptr<const std::vector<sim::Sample>>>> runs_;
};

sim::RunSpec reference_run(const sim::RunSpec& run);

// Largest distance sqrt(|d omega|^2 + |d gamma|^2) between two runs at their
// common output times.
double max_separation(const std::vector<sim::Sample>& a, const std::vector<sim::Sample>& b);

// The finite-time Lyapunov exponent of `run` (docs/cluster.md defines it):
// nullopt when either state's integration fails. `on_window`, if given, sees
// the base state at the end of every window (an energy-momentum map follows
// the fourth integral along the orbit with it).
using FtleState = Eigen::Matrix<double, 6, 1>;

// λ(T): the exponent over the first k windows, T = k · window.
struct FtlePoint {
  double t = 0.0;
  double lambda = 0.0;
};
// The exponent (nullopt: undefined, an integration failed) and, when the
// settings ask for it, λ(T) at k = 1, 2, 4, 8, … windows and at the last
// (until the failure, if one came).
struct FtleResult {
  std::optional<double> value;
  std::vector<FtlePoint> curve;
};
FtleResult ftle_result(const sim::RunSpec& run, const FtleSettings& settings);

std::optional<double> finite_time_lyapunov(
    const sim::RunSpec& run, const FtleSettings& settings,
    const std::function<void(const FtleState&)>& on_window = {});

// The exponent's bookkeeping, window after window: the base state and its
// neighbour, each advanced over one window by the run's own method and
// accuracy (window_run), and the sum of the logarithmic growths.
// finite_time_lyapunov drives it for one point; the batch path
// (batch_points.hpp) for many side by side.
class FtleWindows {
 public:
  FtleWindows(const sim::RunSpec& run, const FtleSettings& settings);

  bool done() const { return failed_ || k_ >= windows_; }
  double window() const { return window_; }
  const FtleState& base() const { return a_; }
  const FtleState& neighbour() const { return b_; }
  // The two states one window later; nullopt where that integration failed,
  // which leaves the exponent undefined.
  void absorb(const std::optional<FtleState>& a, const std::optional<FtleState>& b);
  // Once done(): the exponent, or nullopt.
  std::optional<double> value() const;
  // The exponent and λ(T) as far as it went.
  FtleResult result() const { return {value(), curve_}; }

 private:
  bool curve_wanted_;
  std::vector<FtlePoint> curve_;
  double separation_, window_;
  long windows_, k_ = 0;
  FtleState a_, b_;
  double sum_ = 0.0;
  bool failed_ = false;
};

// The run that advances `x` over one FTLE window: `run` from x, to
// t_end = window with its one sample there.
sim::RunSpec window_run(const sim::RunSpec& run, const FtleState& x, double window);

// Runs that keep at most this many samples keep them all and fold them in
// afterwards; longer ones stream theirs (run_point).
inline constexpr int kKeptSamples = 100'000;

// A point ready to run: what its row says of it besides the run's results,
// and its resolved run. Kept for every point of a sweep before any runs, so
// it holds no more than that (not the point's job fields).
struct PreparedPoint {
  long index = 0;
  std::string axes = "{}";           // the point's axis values, one JSON object
  std::vector<std::string> ignored;  // PointFields::ignored
  sim::RunSpec run;
  // A point of an energy-momentum map: the level its orbits start on (the
  // run's initial state is then unused; sweep/level_point.hpp).
  std::optional<physics::Level> level;
};
PreparedPoint prepared_point(const PointFields& fields, sim::RunSpec run);

// Opens a point's row with the keys every row starts with: the point's
// index, its sweep's hash and its axis values.
void begin_row(io::JsonLine& row, const PreparedPoint& point, const std::string& sweep_hash);

struct PointRow {
  std::string line;     // a JSON object on one line, without the line break
  bool failed = false;  // the run ended in a numerical failure
};

PointRow run_point(const PreparedPoint& point, const std::string& sweep_hash, bool reference,
                   const std::optional<FtleSettings>& ftle, ReferenceCache* cache);

// A run as its row tells it: the result, the largest drift of every
// invariant over its samples, its last sample and, when the reference
// separation needs them, the samples.
struct PointOutcome {
  sim::RunResult result;  // its samples moved to `kept` or dropped
  sim::Drifts drift;
  std::optional<sim::Sample> last;
  std::vector<sim::Sample> kept;
};
// The outcome of a result that holds its samples.
PointOutcome outcome_of(const sim::RunSpec& run, sim::RunResult result, bool keep_samples);

// The row of a point whose run ended as `outcome`. ftle: absent when the
// sweep asks for no exponent, else the exponent (nullopt: undefined) and
// λ(T) when asked for (`ftle_curve`: [[T, λ], …]).
PointRow point_row(const PreparedPoint& point, const std::string& sweep_hash,
                   const PointOutcome& outcome, bool reference, ReferenceCache* cache,
                   const std::optional<FtleResult>& ftle);

}  // namespace epviz::sweep
