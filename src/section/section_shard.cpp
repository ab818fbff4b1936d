#include "section/section_shard.hpp"

#include <filesystem>

namespace epviz::section {

namespace fs = std::filesystem;

shard::RowsShard plan_section_shard(const SectionJob& job, long runs, const shard::ShardSpec& spec,
                                    const std::string& jobs) {
  const auto absolute = [](const fs::path& p) {
    return fs::absolute(p).lexically_normal().string();
  };
  shard::RowsBatch batch{{absolute(job.file), job.hash, {}}, job.csv, runs, "section", ".csv"};
  // The command runs the shard again from any folder: the CSV is absolute.
  auto& command = batch.origin.command;
  command = {"epviz", "section", batch.origin.source, "--out", absolute(job.csv)};
  if (!jobs.empty()) command.insert(command.end(), {"-j", jobs});
  return shard::plan_rows_shard(batch, spec);
}

}  // namespace epviz::section
