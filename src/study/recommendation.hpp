#pragma once
// The answer `epviz bench --job` ends with: which of epviz's methods, at
// which tolerance or step, reaches a named error on the job's body, initial
// state and final time at the least CPU time, and the evidence measured for
// it (time, error against the reference, the largest relative drift of the
// invariants). When no run reaches the error, the one that came closest.
#include <optional>
#include <string>
#include <vector>

#include "study/options.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

// `epviz bench --target-error`'s default: well above the references'
// resolution (their self-check, 1e-14 ... 1e-12) and tight enough for a
// figure that must not move under a closer look.
inline constexpr double kDefaultTargetError = 1e-8;

// The rule, on measured rows: among the successful runs of `impl` whose
// error is finite and at most `target`, the one of least CPU time (ties: the
// fewer evaluations). nullptr when none meets the target.
const WorkPrecisionRow* cheapest_meeting(const std::vector<const WorkPrecisionRow*>& rows,
                                         double target, const std::string& impl = "epviz");
// The successful run of `impl` with the smallest finite error (ties: the
// cheaper); nullptr when there is none.
const WorkPrecisionRow* closest_to_target(const std::vector<const WorkPrecisionRow*>& rows,
                                          const std::string& impl = "epviz");

// One run as evidence: its record, its error at t_end, and the largest
// relative drift among |gamma|^2, C0, C1 (and the fourth integral where the
// case has one) over the run, re-measured at `drift_samples` outputs.
struct Evidence {
  RunRecord run;
  double error = kNaN;
  double drift = kNaN;
  std::string drift_invariant;  // "gamma_norm2", "C0", "C1", "extra"
  int drift_samples = 0;
};

struct Recommendation {
  std::string case_name;
  double t_end = kNaN;
  double target_error = kNaN;
  double reference_self_check = kNaN;  // errors within 10x of it are not resolved
  int compared = 0;                    // epviz's successful runs with an error
  int meeting = 0;                     // of them, those at or below the target
  bool met = false;                    // `choice` meets the target; false: it is the closest run
  std::optional<Evidence> choice;
  std::optional<Evidence> fastest_peer;  // the cheapest peer run meeting the target
};

// The recommendation for problem `p` from the bench's rows (its
// work-precision rows, epviz's and the peers', and its reference row). Re-runs
// the chosen setting once to measure the drift over the whole run.
Recommendation recommend(const Problem& p, const std::vector<StudyRow>& rows, double target_error);

// A short paragraph saying it, with the evidence.
std::string recommendation_text(const Recommendation& r);

}  // namespace epviz::study
