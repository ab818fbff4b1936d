#pragma once
// Peers in `epviz bench`: their work-precision rows in the same shape as
// epviz's own (study "work_precision", impl = the library), and the time ratio
// against epviz's DOP853 at equal achieved error (study "peer_ratio").
#include <string>
#include <vector>

#include "sim/study_bench.hpp"

namespace epviz::peers {

struct PeerStudy {
  std::vector<sim::StudyRow> rows;
  std::vector<std::string> skipped;  // one line per peer that could not run, and why
};

// Same cases, final times, reference and error measure as sim::work_precision_study.
PeerStudy peer_work_precision_study(const sim::StudyOptions& o);

// For each case and peer method, the CPU time ratio peer / epviz DOP853 at
// equal error (log-log interpolation of both sweeps) at the target errors that
// both sweeps span. `rows` holds epviz's and the peers' work-precision rows.
std::vector<sim::StudyRow> equal_error_ratios(const std::vector<sim::StudyRow>& rows,
                                              const std::vector<double>& target_errors);

}  // namespace epviz::peers
