#pragma once
// The rows as `epviz bench` writes them to JSON: one object per row with its
// "study" name and its fields; NaN (not applicable) is written as null, a
// flag as "yes"/"no", a run's outcome as status "ok"/"failed".
#include <nlohmann/json.hpp>
#include <vector>

#include "study/study_row.hpp"

namespace epviz::study {

nlohmann::json row_json(const StudyRow& row);
nlohmann::json rows_json(const std::vector<StudyRow>& rows);

// The whole document `epviz bench --json` writes: "metadata" (the mode,
// `wall_seconds`, the machine, the measures and the references' worst
// self-check) and "rows".
nlohmann::json bench_document(const std::vector<StudyRow>& rows, bool quick, double wall_seconds);

// A number, or null when it is not finite.
nlohmann::json number_or_null(double x);

}  // namespace epviz::study
