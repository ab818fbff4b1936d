#include "study/peers/peer_study.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "study/peers/peers.hpp"
#include "study/reference.hpp"
#include "study/work_precision.hpp"

namespace epviz::study::peers {
namespace {

std::vector<double> peer_tolerances(bool quick) {
  if (quick) return {1e-5, 1e-7, 1e-9, 1e-11};
  return {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
}

// CPU time at error = target along a sweep, interpolated linearly in
// (log10 error, log10 cpu) between the two points around the target, or NaN
// when the sweep does not reach across the target.
double cpu_at_error(std::vector<std::pair<double, double>> error_cpu, double target) {
  std::sort(error_cpu.begin(), error_cpu.end());
  for (std::size_t i = 1; i < error_cpu.size(); ++i) {
    const auto [e0, c0] = error_cpu[i - 1];
    const auto [e1, c1] = error_cpu[i];
    if (e0 <= target && target <= e1 && e0 > 0 && c0 > 0 && c1 > 0) {
      const double s =
          e1 > e0 ? (std::log10(target) - std::log10(e0)) / (std::log10(e1) - std::log10(e0)) : 0.0;
      return std::pow(10.0, std::log10(c0) + s * (std::log10(c1) - std::log10(c0)));
    }
  }
  return kNaN;
}

RunRecord peer_record(const PeerRow& p, const std::string& case_name) {
  RunRecord r;
  r.impl = impl_name(p.id);
  r.case_name = case_name;
  r.formulation = "direct";
  r.method = method_name(p.id);
  r.adaptive = true;
  r.tol = p.tol;
  r.t_end = p.t_end;
  if (p.result.steps >= 0) r.steps = p.result.steps;
  r.rhs_evals = p.result.rhs_evals;
  r.cpu_ms = 1e3 * p.result.cpu_seconds;
  r.repeats = p.result.repeats;
  if (!p.result.ok()) {
    r.ok = false;
    r.failure_t = 0.0;  // the libraries do not say when
    r.failure_reason = p.result.reason;
  }
  return r;
}

}  // namespace

PeerStudy peer_work_precision_study(const StudyOptions& o) {
  PeerStudy out;
  for (const auto& p : problems_of(o)) {
    const double t_end = wp_t_end(p);
    tell(o, "peers: " + p.name);
    const auto ref = compute_reference(p.body, p.initial, t_end, 1, reference_step(p.initial));
    for (const auto& peer :
         peer_work_precision(p.body, p.initial, peer_tolerances(o.quick), t_end, repeats_of(o))) {
      if (peer.result.status == PeerStatus::skipped) {
        const std::string line =
            impl_name(peer.id) + " " + method_name(peer.id) + ": skipped: " + peer.result.reason;
        if (std::find(out.skipped.begin(), out.skipped.end(), line) == out.skipped.end())
          out.skipped.push_back(line);
        continue;
      }
      WorkPrecisionRow row{peer_record(peer, p.name)};
      if (peer.result.ok()) {
        sim::Sample s;
        s.omega = peer.result.omega;
        s.gamma = peer.result.gamma;
        row.error = state_error(s, ref.samples.back());
      }
      row.error_resolved = std::isfinite(row.error) && row.error > 10.0 * ref.self_check;
      out.rows.push_back(std::move(row));
    }
  }
  return out;
}

std::vector<PeerRatioRow> equal_error_ratios(const std::vector<const WorkPrecisionRow*>& rows,
                                             const std::vector<double>& target_errors) {
  // (case, impl, method) -> (error, cpu_ms) of the resolved, successful runs.
  std::map<std::tuple<std::string, std::string, std::string>,
           std::vector<std::pair<double, double>>>
      sweeps;
  for (const auto* r : rows) {
    if (!r->run.ok || !r->error_resolved || r->run.formulation != "direct") continue;
    if (!std::isfinite(r->error) || !std::isfinite(r->run.cpu_ms)) continue;
    sweeps[{r->run.case_name, r->run.impl, r->run.method}].emplace_back(r->error, r->run.cpu_ms);
  }
  std::vector<PeerRatioRow> out;
  for (const auto& [key, sweep] : sweeps) {
    const auto& [c, impl, method] = key;
    if (impl == "epviz") continue;
    const auto base = sweeps.find({c, "epviz", "dop853"});
    if (base == sweeps.end()) continue;
    for (const double target : target_errors) {
      const double peer = cpu_at_error(sweep, target), ours = cpu_at_error(base->second, target);
      if (!std::isfinite(peer) || !std::isfinite(ours)) continue;
      out.push_back({c, impl, method, target, peer, ours, peer / ours});
    }
  }
  return out;
}

}  // namespace epviz::study::peers
