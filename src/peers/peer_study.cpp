#include "peers/peer_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "peers/peers.hpp"
#include "sim/study_reference.hpp"

namespace epviz::peers {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> peer_tolerances(bool quick) {
  if (quick) return {1e-5, 1e-7, 1e-9, 1e-11};
  return {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
}

// log10(cpu) at log10(error) = target along a sweep sorted by error, or NaN
// when the sweep does not reach across the target.
double cpu_at_error(std::vector<std::pair<double, double>> error_cpu, double target) {
  std::sort(error_cpu.begin(), error_cpu.end());
  for (std::size_t i = 1; i < error_cpu.size(); ++i) {
    const auto [e0, c0] = error_cpu[i - 1];
    const auto [e1, c1] = error_cpu[i];
    if (e0 <= target && target <= e1 && e0 > 0 && c0 > 0 && c1 > 0) {
      const double s = e1 > e0 ? (std::log10(target) - std::log10(e0)) / (std::log10(e1) - std::log10(e0)) : 0.0;
      return std::pow(10.0, std::log10(c0) + s * (std::log10(c1) - std::log10(c0)));
    }
  }
  return kNaN;
}

}  // namespace

PeerStudy peer_work_precision_study(const sim::StudyOptions& o) {
  PeerStudy out;
  const int repeats = o.repeats > 0 ? o.repeats : (o.quick ? 3 : 5);
  std::vector<physics::Case> cases = o.cases;
  if (cases.empty())
    for (const auto& p : physics::case_presets()) cases.push_back(p.id);
  for (const auto c : cases) {
    const auto& p = physics::preset(c);
    const double t_end = sim::wp_t_end(c);
    const auto ref = sim::compute_reference(p.body, p.initial, t_end, 1, sim::reference_step(p.initial));
    for (const auto& r : peer_work_precision(c, peer_tolerances(o.quick), t_end, repeats)) {
      if (r.status == "skipped") {
        const std::string line = r.impl + " " + r.method + ": skipped: " + r.reason;
        if (std::find(out.skipped.begin(), out.skipped.end(), line) == out.skipped.end()) out.skipped.push_back(line);
        continue;
      }
      sim::StudyRow row;
      row.study = "work_precision";
      row.set("impl", r.impl);
      row.set("case", physics::case_name(c));
      row.set("formulation", "direct");
      row.set("method", r.method);
      row.set("accuracy", "tol");
      row.set("tol", r.tol);
      row.set("step", kNaN);
      row.set("t_end", r.t_end);
      row.set("steps", r.steps >= 0 ? double(r.steps) : kNaN);
      row.set("rhs_evals", double(r.rhs_evals));
      row.set("flow_evals", 0.0);
      row.set("cpu_ms", r.cpu_ms);
      row.set("repeats", double(r.repeats));
      const bool ok = r.status == "ok";
      row.set("status", ok ? "ok" : "failed");
      row.set("failure_t", ok ? kNaN : 0.0);
      row.set("failure_reason", ok ? std::string() : r.reason);
      sim::Sample s;
      s.omega = r.omega;
      s.gamma = r.gamma;
      const double err = ok ? sim::state_error(s, ref.samples.back()) : kNaN;
      row.set("error", err);
      row.set("error_resolved", std::isfinite(err) && err > 10.0 * ref.self_check ? "yes" : "no");
      out.rows.push_back(std::move(row));
    }
  }
  return out;
}

std::vector<sim::StudyRow> equal_error_ratios(const std::vector<sim::StudyRow>& rows,
                                              const std::vector<double>& target_errors) {
  // (case, impl, method) -> (error, cpu_ms) of the resolved, successful runs.
  std::map<std::tuple<std::string, std::string, std::string>, std::vector<std::pair<double, double>>> sweeps;
  for (const auto& r : rows) {
    if (r.study != "work_precision" || r.text_of("status") != std::optional<std::string>("ok")) continue;
    if (r.text_of("error_resolved") != std::optional<std::string>("yes")) continue;
    if (r.text_of("formulation") != std::optional<std::string>("direct")) continue;
    const auto e = r.number("error"), c = r.number("cpu_ms");
    if (!e || !c || !std::isfinite(*e) || !std::isfinite(*c)) continue;
    sweeps[{*r.text_of("case"), *r.text_of("impl"), *r.text_of("method")}].emplace_back(*e, *c);
  }
  std::vector<sim::StudyRow> out;
  for (const auto& [key, sweep] : sweeps) {
    const auto& [c, impl, method] = key;
    if (impl == "epviz") continue;
    const auto base = sweeps.find({c, "epviz", "dop853"});
    if (base == sweeps.end()) continue;
    for (const double target : target_errors) {
      const double peer = cpu_at_error(sweep, target), ours = cpu_at_error(base->second, target);
      if (!std::isfinite(peer) || !std::isfinite(ours)) continue;
      sim::StudyRow row;
      row.study = "peer_ratio";
      row.set("case", c);
      row.set("impl", impl);
      row.set("method", method);
      row.set("error", target);
      row.set("peer_cpu_ms", peer);
      row.set("epviz_dop853_cpu_ms", ours);
      row.set("ratio", peer / ours);
      out.push_back(std::move(row));
    }
  }
  return out;
}

}  // namespace epviz::peers
