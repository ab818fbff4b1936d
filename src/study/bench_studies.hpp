#pragma once
// Every study of `epviz bench`, in the order its tables print: work-precision
// (epviz's methods, then the peers and their CPU-time ratios), invariant
// drift, invariant cost and the five stability studies. With a body of one's
// own and no preset named, only the first two: those run on that body.
#include <functional>
#include <string>
#include <vector>

#include "study/options.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

// The error levels at which the peers' CPU time is compared with epviz's DOP853.
inline const std::vector<double> kPeerRatioErrors{1e-6, 1e-8, 1e-10};

// `note` is told each stage as it starts ("invariant drift...") and each peer
// that could not run, and why, one line each.
std::vector<StudyRow> bench_studies(const StudyOptions& o,
                                    const std::function<void(const std::string&)>& note);

}  // namespace epviz::study
