#pragma once
// What `epviz merge` finds in a directory the shards wrote to: the batches
// (the shards of one sweep or render share a kind and a hash), each shard by
// its manifest, and what keeps a batch from being merged (a shard missing,
// not completed, or whose files changed since), with the command that redoes
// that shard.
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "shard/manifest.hpp"

namespace epviz::shard {

struct Batch {
  std::string kind, hash;
  long count = 0;
  std::map<long, Manifest> shards;    // by shard index
  std::vector<std::string> problems;  // one line each, with the command that redoes the shard
  long unlisted = 0;                  // shards with problems past max_listed_problems, counted only
  std::vector<long> incomplete;       // every shard with a problem, by index, in order
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

// Fills b.problems (the first max_listed_problems), b.unlisted and
// b.incomplete from the manifests and the files on disk now.
void check_batch(Batch& b, const std::filesystem::path& dir);

}  // namespace epviz::shard
