#pragma once
// What redoes the incomplete shards of a merge on Slurm: a shell script that
// submits one job array per incomplete batch, with only the failed shards'
// indices (`--array=2,5-7`), and the same merge again once they have ended
// (`--dependency=afterany`, so that the merge runs, and reports, even if a
// task fails once more). Each task passes its shard as `--shard
// $SLURM_ARRAY_TASK_ID/N`, which does not depend on the array's numbering.
#include <filesystem>
#include <string>
#include <vector>

#include "shard/batch.hpp"

namespace epviz::shard {

// "2,5-7": the indices (sorted, distinct) as Slurm's --array list.
std::string index_ranges(const std::vector<long>& indices);

// The script's text. `merge_command` is the merge to run after the shards
// (its words, quoted here); batches without incomplete shards are skipped.
std::string slurm_resubmit_script(const std::vector<Batch>& batches,
                                  const std::vector<std::string>& merge_command);

}  // namespace epviz::shard
