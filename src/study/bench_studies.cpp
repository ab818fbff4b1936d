#include "study/bench_studies.hpp"

#include "study/invariant_cost.hpp"
#include "study/invariant_drift.hpp"
#include "study/peers/peer_study.hpp"
#include "study/pole_passage.hpp"
#include "study/stability.hpp"
#include "study/work_precision.hpp"

namespace epviz::study {

std::vector<StudyRow> bench_studies(const StudyOptions& o,
                                    const std::function<void(const std::string&)>& note) {
  std::vector<StudyRow> rows;
  note("work-precision...");
  append(rows, work_precision_study(o));
  note("peers (Boost.Odeint, GSL, SciPy where available)...");
  auto peer_study = peers::peer_work_precision_study(o);
  for (const auto& line : peer_study.skipped) note(line);
  append(rows, std::move(peer_study.rows));
  append(rows, peers::equal_error_ratios(rows_of<WorkPrecisionRow>(rows), kPeerRatioErrors));
  // The other studies are of the presets: a job alone is studied alone.
  if (cases_of(o).empty()) return rows;
  note("invariant drift...");
  append(rows, drift_study(o));
  note("invariant cost...");
  append(rows, invariant_cost_study(o));
  note("stability...");
  append(rows, stability_max_step(o));
  append(rows, stability_pole(o));
  append(rows, stability_separatrix(o));
  append(rows, stability_sleeping(o));
  append(rows, stability_chaos(o));
  return rows;
}

}  // namespace epviz::study
