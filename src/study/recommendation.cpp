#include "study/recommendation.hpp"

#include <cmath>
#include <cstdio>
#include <exception>

#include "io/number_text.hpp"
#include "physics/notation.hpp"
#include "sim/drift.hpp"
#include "sim/trajectory.hpp"
#include "study/work_precision.hpp"

namespace epviz::study {
namespace {

bool measured(const WorkPrecisionRow& r, const std::string& impl) {
  return r.run.impl == impl && r.run.ok && std::isfinite(r.error) && std::isfinite(r.run.cpu_ms);
}

// Less CPU time first; at equal time, fewer evaluations.
bool cheaper(const WorkPrecisionRow& a, const WorkPrecisionRow& b) {
  if (a.run.cpu_ms != b.run.cpu_ms) return a.run.cpu_ms < b.run.cpu_ms;
  return a.run.cost() < b.run.cost();
}

// The largest relative drift of the invariants at every accepted step of the
// run `row` describes, and which invariant it is.
void measure_drift(const Problem& p, const RunRecord& run, Evidence& e) {
  const auto method = sim::method_from_name(run.method);
  const auto formulation = sim::formulation_from_name(run.formulation);
  if (!method || !formulation) return;
  sim::RunSpec spec = problem_run(p, *method, *formulation, run.t_end, 1);
  if (run.adaptive)
    spec.tol = run.tol;
  else
    spec.step = run.step;
  const sim::InvariantMonitor monitor(p.body, p.id, p.initial);
  sim::Drifts worst = monitor.no_drift();
  int steps = 0;
  try {
    auto trajectory = sim::Trajectory::start(spec);
    trajectory->observe_steps([&](const sim::Sample& s) {
      monitor.worsen(worst, s);
      ++steps;
    });
    trajectory->next();
  } catch (const std::exception&) {
    // The measured row succeeded, so this cannot happen but by a change of
    // the run; the drift seen up to the failure is still the evidence.
  }
  const std::pair<double, const char*> drifts[] = {{worst.gamma_norm2, "gamma_norm2"},
                                                   {worst.area, "C0"},
                                                   {worst.energy, "C1"},
                                                   {worst.extra.value_or(0.0), "extra"}};
  e.drift = 0.0;
  e.drift_invariant = "gamma_norm2";
  for (const auto& [d, name] : drifts)
    if (!(d <= e.drift)) {  // NaN wins: the worst there is
      e.drift = d;
      e.drift_invariant = name;
    }
  e.drift_samples = steps;
}

Evidence evidence_of(const WorkPrecisionRow& row) { return {row.run, row.error, kNaN, {}, 0}; }

std::string short_number(double v) { return io::number_text(v, 2); }

// "dop853 (direct) at tol 1e-10", "gauss6 (spinor) at step 0.0125".
std::string setting(const RunRecord& r) {
  std::string s = r.method;
  if (r.impl != "epviz") s = r.impl + " " + s;
  if (!r.formulation.empty()) s += " (" + r.formulation + ")";
  s += r.adaptive ? " at tol " + short_number(r.tol) : " at step " + short_number(r.step);
  return s;
}

std::string invariant_label(const std::string& key) {
  if (key == "gamma_norm2") return std::string(physics::symbol::gamma_norm2);
  if (key == "C0") return std::string(physics::symbol::area);
  if (key == "C1") return std::string(physics::symbol::energy);
  return "the fourth integral";
}

std::string measures(const Evidence& e) {
  std::string s = short_number(e.run.cpu_ms) + " ms CPU time, ";
  s += std::to_string(e.run.cost()) + " evaluations, error ";
  s += short_number(e.error);
  if (std::isfinite(e.drift)) {
    s += ", largest relative drift ";
    s += short_number(e.drift) + " (" + invariant_label(e.drift_invariant) + ", over ";
    s += std::to_string(e.drift_samples) + " steps)";
  }
  return s;
}

}  // namespace

const WorkPrecisionRow* cheapest_meeting(const std::vector<const WorkPrecisionRow*>& rows,
                                         double target, const std::string& impl) {
  const WorkPrecisionRow* best = nullptr;
  for (const auto* r : rows)
    if (measured(*r, impl) && r->error <= target && (!best || cheaper(*r, *best))) best = r;
  return best;
}

const WorkPrecisionRow* closest_to_target(const std::vector<const WorkPrecisionRow*>& rows,
                                          const std::string& impl) {
  const WorkPrecisionRow* best = nullptr;
  for (const auto* r : rows)
    if (measured(*r, impl) &&
        (!best || r->error < best->error || (r->error == best->error && cheaper(*r, *best))))
      best = r;
  return best;
}

Recommendation recommend(const Problem& p, const std::vector<StudyRow>& rows, double target_error) {
  Recommendation out;
  out.case_name = p.name;
  out.t_end = wp_t_end(p);
  out.target_error = target_error;
  // The job's rows: its case name and final time (a job of a preset's case
  // shares the name with the preset's own rows, not their final time).
  std::vector<const WorkPrecisionRow*> mine;
  for (const auto* r : rows_of<WorkPrecisionRow>(rows))
    if (r->run.case_name == p.name && r->run.t_end == out.t_end) mine.push_back(r);
  for (const auto* r : rows_of<ReferenceRow>(rows))
    if (r->case_name == p.name && r->t_end == out.t_end) out.reference_self_check = r->self_check;
  for (const auto* r : mine)
    if (measured(*r, "epviz")) {
      ++out.compared;
      if (r->error <= target_error) ++out.meeting;
    }
  const auto* choice = cheapest_meeting(mine, target_error);
  out.met = choice != nullptr;
  if (!choice) choice = closest_to_target(mine);
  if (choice) {
    out.choice = evidence_of(*choice);
    measure_drift(p, choice->run, *out.choice);
  }
  const WorkPrecisionRow* peer = nullptr;
  for (const char* impl : {"boost-odeint", "gsl", "scipy"})
    if (const auto* best = cheapest_meeting(mine, target_error, impl);
        best && (!peer || cheaper(*best, *peer)))
      peer = best;
  if (peer) out.fastest_peer = evidence_of(*peer);
  return out;
}

std::string recommendation_text(const Recommendation& r) {
  std::string head = "Recommendation for " + r.case_name + " to t = " + short_number(r.t_end) +
                     " at error <= " + short_number(r.target_error) + ": ";
  if (!r.choice) return head + "no run of epviz's methods finished with an error to compare.\n";
  const Evidence& c = *r.choice;
  std::string text = head;
  if (r.met) {
    text += setting(c.run) + ", the cheapest of the " + std::to_string(r.meeting) + " of " +
            std::to_string(r.compared) + " runs that meet it: " + measures(c) + ".";
  } else {
    text += "none of the " + std::to_string(r.compared) + " runs meets it; the closest is " +
            setting(c.run) + ": " + measures(c) + ".";
  }
  if (r.fastest_peer) {
    const Evidence& q = *r.fastest_peer;
    text += " The fastest peer that meets it is " + setting(q.run) + ": " +
            short_number(q.run.cpu_ms) + " ms, error " + short_number(q.error);
    if (r.met && c.run.cpu_ms > 0.0)
      text += " (" + short_number(q.run.cpu_ms / c.run.cpu_ms) + "x the time)";
    text += ".";
  } else {
    text += " No peer run meets it.";
  }
  if (std::isfinite(r.reference_self_check) && r.target_error < 10.0 * r.reference_self_check)
    text += " The reference resolves errors only down to " +
            short_number(10.0 * r.reference_self_check) + ".";
  return text + "\n";
}

}  // namespace epviz::study
