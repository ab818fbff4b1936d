#pragma once
// The rows of a sweep batch's shards joined into one list: every row is one
// of its shard's points (its "index" within the shard's items and its
// "sweep" the batch's hash), none missing, and a point twice only as the same
// row (same_row; kept once).
#include <filesystem>
#include <functional>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "shard/batch.hpp"

namespace epviz::shard {

// Whether two rows of one point are the same result: equal but for the CPU
// time each run measured ("cpu_seconds", sweep/run_record.cpp), so that two
// runs of a point (a shard run twice) give the same row.
bool same_row(const nlohmann::json& a, const nlohmann::json& b);

// What is wrong with a row's values that the merge reads beyond "index" and
// "sweep" ("key 'ftle_curve': ..."), or "" when nothing is.
using RowCheck = std::function<std::string(const nlohmann::json& row)>;

// Sorted by index. Throws io::BadInput naming the file and the row, or the
// missing point with the command that redoes its shard; and, for a row that
// `check` finds wrong, the file, the line and what `check` says.
std::vector<nlohmann::json> merged_rows(const Batch& b, const std::filesystem::path& dir,
                                        const RowCheck& check = {});

}  // namespace epviz::shard
