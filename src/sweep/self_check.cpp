#include "sweep/self_check.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "io/bad_input.hpp"
#include "io/number_text.hpp"
#include "job/resolve.hpp"
#include "sim/simulate.hpp"
#include "sweep/level_point.hpp"
#include "sweep/point_run.hpp"
#include "sweep/sweep_point.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;

std::string metric_name(const std::string& metric) {
  return metric == "ftle" ? "FTLE" : metric == "reference_error" ? "reference error" : metric;
}

std::optional<double> number_in(const Json& row, const std::string& key) {
  if (!row.contains(key) || !row[key].is_number()) return std::nullopt;
  return row[key].get<double>();
}

// The point's run made `tighter` times more accurate (self_check.hpp says how).
sim::RunSpec tightened(sim::RunSpec run, double tighter) {
  if (sim::is_adaptive(run.method))
    run.tol /= tighter;
  else
    run.step /= std::pow(tighter, 1.0 / double(sim::order(run.method)));
  return run;
}

// How the FTLE's runs were tightened, for the report: "tol / 100",
// "step / 100^(1/order)" or both, as the sampled methods are adaptive or not.
std::string ftle_tightening(const std::vector<sim::RunSpec>& runs, double tighter) {
  char factor[32];
  std::snprintf(factor, sizeof factor, "%g", tighter);
  bool adaptive = false, fixed = false;
  for (const auto& r : runs) (sim::is_adaptive(r.method) ? adaptive : fixed) = true;
  std::string out;
  if (adaptive) out = std::string("tol / ") + factor;
  if (fixed) out += std::string(adaptive ? ", " : "") + "step / " + factor + "^(1/order)";
  return out;
}

// The reference error of `run` against its reference made `tighter` times more accurate.
std::optional<double> tighter_reference_error(const sim::RunSpec& run, double tighter) {
  sim::RunSpec reference = reference_run(run);
  reference.tol /= tighter;
  try {
    const auto own = sim::simulate(run);
    const auto ref = sim::simulate(reference);
    if (ref.failure) return std::nullopt;
    return max_separation(own.samples, ref.samples);
  } catch (const std::exception&) {
    return std::nullopt;  // as a reference that cannot run: no value
  }
}

}  // namespace

std::vector<long> self_check_sample(long points) {
  if (points <= 0) return {};
  const long share = long(std::ceil(kSelfCheckShare * double(points)));
  const long n = std::min(points, std::max(kSelfCheckMinPoints, share));
  std::vector<long> out;
  out.reserve(std::size_t(n));
  // The middle of each of n equal stretches of the index range: a regular
  // sample, so that it crosses every axis rather than one corner of the grid.
  for (long k = 0; k < n; ++k) out.push_back(long((double(k) + 0.5) * double(points) / double(n)));
  return out;
}

std::vector<std::string> checked_metrics(const SweepSpec& spec) {
  std::vector<std::string> m;
  if (spec.ftle) m.emplace_back("ftle");
  if (spec.reference) m.emplace_back("reference_error");
  return m;
}

bool SelfCheck::converged() const {
  return std::all_of(metrics.begin(), metrics.end(),
                     [](const MetricCheck& m) { return m.converged(); });
}

const MetricCheck* SelfCheck::find(const std::string& metric) const {
  for (const auto& m : metrics)
    if (m.metric == metric) return &m;
  return nullptr;
}

double colour_range(const std::string& metric, const std::vector<Json>& rows,
                    const std::vector<AtlasRequest>& atlases) {
  for (const auto& a : atlases)
    if (a.metric == metric && std::isfinite(a.min) && std::isfinite(a.max)) return a.max - a.min;
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& r : rows)
    if (const auto v = number_in(r, metric); v && std::isfinite(*v)) {
      lo = std::min(lo, *v);
      hi = std::max(hi, *v);
    }
  if (!(hi >= lo)) return 0.0;
  // A bar of one value: its size stands for the range.
  return hi > lo ? hi - lo : std::abs(hi);
}

SelfCheck run_self_check(const SweepSpec& spec, const std::vector<Json>& rows,
                         const std::vector<AtlasRequest>& atlases, int threads, double tighter) {
  SelfCheck check;
  check.threshold = spec.self_check_threshold;
  const auto metrics = checked_metrics(spec);
  if (metrics.empty()) return check;
  std::map<long, const Json*> by_index;
  for (const auto& r : rows) by_index[r["index"].get<long>()] = &r;
  const auto sample = self_check_sample(spec.point_count());
  check.sampled = long(sample.size());

  // Resolved as the sweep resolved them (sweep_runner.cpp), one at a time:
  // the reader keeps what it has read.
  PointReader read_point(spec);
  std::vector<sim::RunSpec> runs;
  std::vector<std::optional<physics::Level>> levels;
  for (long i : sample) {
    if (!by_index.count(i))
      throw io::BadInput(spec.file + ": the self-check's point " + std::to_string(i) +
                         " has no row");
    try {
      const auto p = read_point(i);
      runs.push_back(
          resolve_point(p, [](const job::SimulationFields& f) { return job::resolve(f); }));
      levels.push_back(prepared_point(p, runs.back()).level);
    } catch (const std::invalid_argument& e) {
      throw io::BadInput(e.what());
    }
  }

  std::vector<SampledValue> values(sample.size() * metrics.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex lock;
  auto work = [&] {
    for (;;) {
      const std::size_t k = next.fetch_add(1);
      if (k >= sample.size()) return;
      try {
        const Json& row = *by_index.at(sample[k]);
        for (std::size_t m = 0; m < metrics.size(); ++m) {
          SampledValue& v = values[k * metrics.size() + m];
          v.index = sample[k];
          v.metric = metrics[m];
          v.value = number_in(row, metrics[m]);
          // A level's FTLE is the largest of its orbits' (sweep/level_point.hpp).
          v.tighter = metrics[m] != "ftle" ? tighter_reference_error(runs[k], tighter)
                      : levels[k]          ? level_metrics(tightened(runs[k], tighter), *levels[k],
                                                           spec.level_orbits, *spec.ftle)
                                        .largest_ftle
                                  : finite_time_lyapunov(tightened(runs[k], tighter), *spec.ftle);
        }
      } catch (...) {
        std::lock_guard g(lock);
        if (!error) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  const int n = std::max(1, std::min(threads, int(sample.size())));
  for (int t = 1; t < n; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);

  for (const auto& metric : metrics) {
    MetricCheck c;
    c.metric = metric;
    c.tightened = metric == "ftle" ? ftle_tightening(runs, tighter)
                                   : "reference tol " + io::number_text(1e-13 / tighter, 2);
    c.range = colour_range(metric, rows, atlases);
    c.limit = check.threshold * c.range;
    for (const auto& v : values) {
      if (v.metric != metric) continue;
      const bool a = v.value && std::isfinite(*v.value), b = v.tighter && std::isfinite(*v.tighter);
      if (a != b) ++c.one_sided;
      if (!a || !b) continue;
      ++c.compared;
      const double change = std::abs(*v.tighter - *v.value);
      if (c.worst_index < 0 || change > c.largest_change) {
        c.largest_change = change;
        c.worst_index = v.index;
      }
    }
    check.metrics.push_back(c);
  }
  check.values = std::move(values);
  return check;
}

Json self_check_json(const SelfCheck& check) {
  Json j;
  j["threshold"] = check.threshold;
  j["sampled_points"] = check.sampled;
  j["converged"] = check.converged();
  j["metrics"] = Json::object();
  for (const auto& m : check.metrics) {
    Json& o = j["metrics"][m.metric];
    o["tightened"] = m.tightened;
    o["compared"] = m.compared;
    o["one_sided"] = m.one_sided;
    o["largest_change"] = m.largest_change;
    o["worst_index"] = m.worst_index >= 0 ? Json(m.worst_index) : Json(nullptr);
    o["colour_range"] = m.range;
    o["limit"] = m.limit;
    o["converged"] = m.converged();
  }
  j["points"] = Json::array();
  for (const auto& v : check.values) {
    const auto num = [](const std::optional<double>& x) {
      return x && std::isfinite(*x) ? Json(*x) : Json(nullptr);
    };
    j["points"].push_back({{"index", v.index},
                           {"metric", v.metric},
                           {"value", num(v.value)},
                           {"tighter", num(v.tighter)}});
  }
  return j;
}

std::string self_check_file_name(const std::string& rows_name) {
  std::string stem = rows_name;
  if (stem.ends_with(".jsonl")) stem.resize(stem.size() - 6);
  return stem + ".self_check.json";
}

std::vector<std::string> self_check_lines(const SelfCheck& check) {
  std::vector<std::string> out;
  for (const auto& m : check.metrics) {
    std::string line = "self-check " + m.metric + " (" + m.tightened + ", " +
                       std::to_string(check.sampled) + " points): largest change " +
                       io::number_text(m.largest_change, 2);
    if (m.worst_index >= 0) line += " at point " + std::to_string(m.worst_index);
    line += ", limit " + io::number_text(m.limit, 2) + " (" +
            io::number_text(100 * check.threshold, 2) + " % of the colour bar's range " +
            io::number_text(m.range, 2) + ")";
    if (m.one_sided)
      line += ", " + std::to_string(m.one_sided) + " points with a value only one of the two times";
    line += m.converged() ? ": converged" : ": NOT CONVERGED, tighten tol";
    out.push_back(line);
  }
  return out;
}

std::string self_check_caption(const SelfCheck& check, const std::string& metric) {
  const MetricCheck* m = check.find(metric);
  if (!m) return "";
  std::string on = " on ";
  on += std::to_string(check.sampled);
  on += " sampled points";
  const std::string what = metric_name(metric);
  if (m->converged()) return what + " converged to ±" + io::number_text(m->largest_change, 2) + on;
  std::string why =
      what + " ±" + io::number_text(m->largest_change, 2) + " > " + io::number_text(m->limit, 2);
  if (m->one_sided) {
    why += ", ";
    why += std::to_string(m->one_sided);
    why += " failed once";
  }
  return "not converged: tighten tol (" + why + on + ")";
}

}  // namespace epviz::sweep
