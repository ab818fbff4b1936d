#pragma once
// Peers in `epviz bench`: their work-precision rows in the same record as
// epviz's own (WorkPrecisionRow, run.impl = the library), and the CPU time
// ratio against epviz's DOP853 at equal achieved error (PeerRatioRow).
#include <string>
#include <vector>

#include "study/options.hpp"
#include "study/study_row.hpp"

namespace epviz::study::peers {

struct PeerStudy {
  std::vector<WorkPrecisionRow> rows;
  std::vector<std::string> skipped;  // one line per peer that could not run, and why
};

// Same problems (the presets and a job's body), final times, reference and
// error measure as study::work_precision_study.
PeerStudy peer_work_precision_study(const StudyOptions& o);

// For each case and peer method, the CPU time ratio peer / epviz DOP853 at
// equal error (log-log interpolation of both sweeps) at the target errors that
// both sweeps span. `rows` holds epviz's and the peers' work-precision rows.
std::vector<PeerRatioRow> equal_error_ratios(const std::vector<const WorkPrecisionRow*>& rows,
                                             const std::vector<double>& target_errors);

}  // namespace epviz::study::peers
