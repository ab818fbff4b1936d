#pragma once
// A sweep's check of its own accuracy. A metric that depends on how
// accurately the points were integrated (the FTLE, the error against the
// reference) is worth drawing only if a tighter integration would draw the
// same map. So a deterministic sample of the points (at least 16, or 2 % of
// them, spread over the index range) is run again 100x tighter and each
// metric's largest change is compared with a share (the sweep's
// "self_check": {"threshold"}, default 5 %) of the range of the colour bar it
// is drawn with.
//
// What "100x tighter" means for each metric:
// - ftle: the point's own run with its tol divided by 100; a fixed-step
//   method's step divided by 100^(1/order), which shrinks its global error
//   100-fold (the point's method stays: the FTLE is of its run).
// - reference_error: the reference, dop853 at tol 1e-13, redone at 1e-15.
//   The error of the point's own run is what the metric measures; what can
//   spoil it is a reference no better than the run.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {

inline constexpr long kSelfCheckMinPoints = 16;
inline constexpr double kSelfCheckShare = 0.02;   // of the sweep's points
inline constexpr double kSelfCheckTighter = 100;  // how much tighter the sample runs

// The points of a sweep of `points` points the check reruns, ascending:
// min(points, max(16, ceil(2 % of points))) indices spread evenly over
// 0..points-1. Every shard and every merge of a sweep agrees on them.
std::vector<long> self_check_sample(long points);

// The metrics a sweep's rows hold that the check covers: "ftle" when the
// sweep computes it, "reference_error" when it has a reference.
std::vector<std::string> checked_metrics(const SweepSpec& spec);

struct MetricCheck {
  std::string metric;           // "ftle" or "reference_error"
  std::string tightened;        // "tol / 100", "step / 100^(1/order)", "reference tol 1e-15"
  long compared = 0;            // sampled points with a value both times
  long one_sided = 0;           // sampled points with a value only one of the two times
  double largest_change = 0.0;  // |tighter - row| over the compared points
  long worst_index = -1;        // the point it was seen at; -1 without one
  double range = 0.0;           // of the colour bar
  double limit = 0.0;           // threshold x range
  bool converged() const { return one_sided == 0 && largest_change <= limit; }
};

struct SampledValue {
  long index = 0;
  std::string metric;
  std::optional<double> value, tighter;  // in the row; at the tighter setting
};

struct SelfCheck {
  double threshold = 0.05;  // the sweep's share of the colour bar
  long sampled = 0;         // points rerun
  std::vector<MetricCheck> metrics;
  std::vector<SampledValue> values;
  bool converged() const;
  const MetricCheck* find(const std::string& metric) const;
};

// The range of the colour bar `metric` is drawn with: the max - min fixed by
// an atlas of `atlases` that draws it, else the span of its values in `rows`.
double colour_range(const std::string& metric, const std::vector<nlohmann::json>& rows,
                    const std::vector<AtlasRequest>& atlases);

// Reruns the sample of `spec`'s points tighter on `threads` threads and
// compares with `rows` (every point's row, any order). `atlases`: the
// figures being drawn, whose fixed ranges set the limits. An empty check (no
// metrics) for a sweep with neither FTLE nor reference. `tighter`: for the
// tests (1 must give no change at all).
SelfCheck run_self_check(const SweepSpec& spec, const std::vector<nlohmann::json>& rows,
                         const std::vector<AtlasRequest>& atlases, int threads,
                         double tighter = kSelfCheckTighter);

// The check as JSON (written beside the merged rows): the threshold, each
// metric's largest change, range, limit and verdict, and every sampled value.
nlohmann::json self_check_json(const SelfCheck& check);

// "chaos_map.jsonl" -> "chaos_map.self_check.json": where the check of a
// sweep's merged rows goes, beside them.
std::string self_check_file_name(const std::string& rows_name);

// One line per metric for the merge's output.
std::vector<std::string> self_check_lines(const SelfCheck& check);

// The verdict an atlas of `metric` adds to its title; "" when the check does
// not cover it. "FTLE converged to ±0.003 on 82 sampled points" or
// "not converged: tighten tol (FTLE ±0.04 > 0.015 on 82 sampled points)".
std::string self_check_caption(const SelfCheck& check, const std::string& metric);

}  // namespace epviz::sweep
