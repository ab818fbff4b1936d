#pragma once
// The rows as `epviz bench` writes them to JSON: one object per row with its
// "study" name and its fields; NaN (not applicable) is written as null, a
// flag as "yes"/"no", a run's outcome as status "ok"/"failed".
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <vector>

#include "study/recommendation.hpp"
#include "study/study_row.hpp"

namespace epviz::study {

nlohmann::json row_json(const StudyRow& row);
nlohmann::json rows_json(const std::vector<StudyRow>& rows);

// The recommendation for a job (study/recommendation.hpp): its rule, the
// counts, the chosen run and the fastest peer with their evidence (null when
// none), and the paragraph that says it.
nlohmann::json recommendation_json(const Recommendation& r);

// The whole document `epviz bench --json` writes: "metadata" (the mode,
// `wall_seconds`, the machine, the measures and the references' worst
// self-check), "rows", and with a job the "recommendation".
nlohmann::json bench_document(const std::vector<StudyRow>& rows, bool quick, double wall_seconds,
                              const std::optional<Recommendation>& recommendation = std::nullopt);

// A number, or null when it is not finite.
nlohmann::json number_or_null(double x);

}  // namespace epviz::study
