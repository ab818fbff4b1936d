#include "shard/resubmit.hpp"

#include "io/shell_quote.hpp"

namespace epviz::shard {
namespace {

// A command line whose first word is "epviz", run by the job as the binary
// EPVIZ names (as submit.sh and the batch scripts do), else epviz on PATH.
std::string with_binary(const std::string& line) {
  return "\"${EPVIZ:-epviz}\"" + line.substr(std::string("epviz").size());
}

}  // namespace

std::string index_ranges(const std::vector<long>& indices) {
  std::string out;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
    if (!out.empty()) out.push_back(',');
    out += std::to_string(indices[i]);
    if (j > i) {
      out.push_back('-');
      out += std::to_string(indices[j]);
    }
    i = j + 1;
  }
  return out;
}

std::string slurm_resubmit_script(const std::vector<Batch>& batches,
                                  const std::vector<std::string>& merge_command) {
  std::string merge;  // its words quoted, "epviz" first
  for (const auto& w : merge_command) {
    if (!merge.empty()) merge.push_back(' ');
    merge += io::shell_quote(w);
  }
  std::string s =
      "#!/bin/bash\n"
      "# Written by epviz merge --resubmit: submits again, as Slurm job arrays, only the\n"
      "# shards that were missing or incomplete, then the same merge once they have\n"
      "# ended. SBATCH_ARGS (e.g. \"--partition=short\") goes to every sbatch call;\n"
      "# the jobs run the binary EPVIZ names, else epviz on PATH.\n"
      "set -euo pipefail\n"
      "arrays=()\n";
  for (const auto& b : batches) {
    if (b.incomplete.empty()) continue;
    // The task's command: the shard's own, with its index from the array.
    const std::string task = "exec " + with_binary(shell_command(b.shards.begin()->second)) +
                             " --shard \"$SLURM_ARRAY_TASK_ID/" + std::to_string(b.count) + "\"";
    s += "# " + batch_name(b) + ": " + std::to_string(b.incomplete.size()) + " shards\n";
    s += "id=$(sbatch --parsable ${SBATCH_ARGS:-} --array=" + index_ranges(b.incomplete) +
         " --chdir=\"$PWD\" --wrap " + io::shell_quote(task) + ")\n";
    s += "arrays+=(\"${id%%;*}\")\n";
  }
  s += "deps=$(IFS=:; echo \"${arrays[*]}\")\n";
  s += "sbatch --parsable ${SBATCH_ARGS:-} --dependency=afterany:\"$deps\" --chdir=\"$PWD\" "
       "--wrap " +
       io::shell_quote("exec " + with_binary(merge)) + "\n";
  return s;
}

}  // namespace epviz::shard
