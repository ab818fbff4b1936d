#pragma once
// The shard options shared by `epviz sweep` and `epviz render`: --shard I/N,
// or the array job's environment with --shard-count (shard/shard_spec.hpp).
#include <optional>
#include <string>

#include "shard/shard_spec.hpp"

namespace epviz::app {

// nullopt: the whole batch. Throws UsageError naming the option or variable.
std::optional<shard::ShardSpec> shard_from_options(const std::string& shard,
                                                   const std::string& shard_count);

}  // namespace epviz::app
