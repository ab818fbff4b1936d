#pragma once
// A shard of a sweep (`epviz sweep SWEEP --shard I/N`): a contiguous range of
// its points, whose rows go to "<rows>.shard-I-of-N.jsonl" beside the rows
// file asked for, with a manifest (manifest.hpp) that `epviz merge` reads.
// A section's shards (`epviz section FILE --shard I/N`) are planned alike,
// their crossings in "<csv>.shard-I-of-N.csv".
#include <filesystem>
#include <string>
#include <vector>

#include "shard/manifest.hpp"
#include "shard/shard_spec.hpp"

namespace epviz::shard {

// The whole sweep the shards split (or another batch whose shards write
// rows of their items, in order, to one file each: a section's crossings).
struct RowsBatch {
  BatchOrigin origin;          // the sweep file; the hash is of the sweep's content
  std::filesystem::path rows;  // the rows file of the whole sweep ("rows.jsonl")
  long points = 0;
  std::string kind = "sweep";        // the manifests' kind
  std::string extension = ".jsonl";  // of the rows files
};

struct RowsShard {
  ShardSpec shard;
  ItemRange points;            // the points this shard runs
  std::filesystem::path rows;  // where this shard's rows go
  Manifest manifest;
  std::filesystem::path manifest_path;
  std::filesystem::path lock_path;  // held while the shard runs (shard_lock.hpp)
};

RowsShard plan_rows_shard(const RowsBatch& batch, const ShardSpec& spec);

// Writes the manifest with "completed": false (call before running).
void start_rows_shard(const RowsShard& s);
// Adds the rows file, with its checksum, and marks the manifest completed.
void finish_rows_shard(RowsShard& s);

}  // namespace epviz::shard
