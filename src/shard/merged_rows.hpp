#pragma once
// The rows of a sweep batch's shards joined into one list: every row is one
// of its shard's points (its "index" within the shard's items and its
// "sweep" the batch's hash), no point twice and none missing.
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "shard/batch.hpp"

namespace epviz::shard {

// Sorted by index. Throws io::BadInput naming the file and the row, or the
// missing point with the command that redoes its shard.
std::vector<nlohmann::json> merged_rows(const Batch& b, const std::filesystem::path& dir);

}  // namespace epviz::shard
