#pragma once
// What `epviz merge` finds in a directory the shards wrote to: the batches
// (the shards of one sweep or render share a kind and a hash), each shard by
// its manifest, and what keeps a batch from being merged. Each shard is
// complete, running (its lock is held: shard_lock.hpp), dead (not completed,
// its files changed since, or its lock left by a process that is gone) or
// missing; a dead or missing one is named with the command that redoes it, a
// running one is not (a second copy would refuse).
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "shard/manifest.hpp"

namespace epviz::shard {

struct Batch {
  std::string kind, hash;
  std::string stem;  // of the shards' file names: "rows" of "rows.shard-2-of-8.manifest.json"
  long count = 0;
  std::map<long, Manifest> shards;    // by shard index
  std::vector<std::string> problems;  // one line each, with the command that redoes the shard
  long unlisted = 0;                  // shards with problems past max_listed_problems, counted only
  std::vector<long> incomplete;       // every dead or missing shard, by index, in order
  long complete = 0, running = 0, dead = 0, missing = 0;
};

// A batch of a million shards with one manifest must not print a million lines.
inline constexpr std::size_t max_listed_problems = 8;

// "sweep /abs/a.sweep.json (4 shards)".
std::string batch_name(const Batch& b);

// The batches of every manifest in `dir`, in order of kind and hash. Throws
// io::BadInput for a manifest that cannot be read, or for shards of one batch
// that disagree on the number of shards (an old split left beside a new one),
// on the number of items or on the merged output's name.
std::vector<Batch> read_batches(const std::filesystem::path& dir);

// Fills b.problems (the first max_listed_problems), b.unlisted, b.incomplete
// and the counts from the manifests, the locks and the files on disk now.
void check_batch(Batch& b, const std::filesystem::path& dir);

// What merge prints of a checked batch, one line each: its problems, how
// many more were not listed, and "sweep ... (4 shards): 1 complete, 1
// running, 1 dead, 1 missing". Empty for a batch that is complete.
std::vector<std::string> batch_report(const Batch& b);

}  // namespace epviz::shard
