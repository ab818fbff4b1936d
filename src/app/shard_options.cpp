#include "app/shard_options.hpp"

#include "app/cli_values.hpp"
#include "app/usage_error.hpp"

namespace epviz::app {

std::optional<shard::ShardSpec> shard_from_options(const std::string& shard,
                                                   const std::string& shard_count) {
  try {
    const long count =
        shard_count.empty() ? 0 : parse_integer("--shard-count", shard_count, 1, shard::max_shards);
    if (!shard.empty()) {
      const auto s = shard::parse_shard(shard, "--shard");
      if (count && count != s.count)
        throw UsageError("--shard-count: " + std::to_string(count) + " disagrees with --shard " +
                         shard + "; give one of them");
      return s;
    }
    return shard::shard_from_environment(shard::process_environment(), count);
  } catch (const shard::ShardError& e) {
    throw UsageError(e.what());
  }
}

}  // namespace epviz::app
