#pragma once
// A shard of a render (`epviz render JOB --shard I/N`): a contiguous range of
// the job's frames. Every shard integrates from t = 0 through the frames
// before its range (as --frames does), so that trails and states, and thus
// the PNG bytes, are those of the unsharded render. PNG frames keep their
// absolute numbers; a video shard writes a segment "<name>.shard-I-of-N.<ext>"
// that `epviz merge` joins. Each shard writes a manifest (manifest.hpp)
// beside its output.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shard/manifest.hpp"
#include "shard/shard_lock.hpp"
#include "shard/shard_spec.hpp"

namespace epviz::shard {

// The whole render the shards split, as the command that draws it knows it.
struct FrameBatch {
  BatchOrigin origin;           // the job file; the hash is of the job as drawn
  std::filesystem::path dir;    // where the frames or the video go
  std::string name;             // PNG frame prefix or video file stem
  std::string video_extension;  // ".mp4", ".webm", ".gif"; "" for PNG frames
  int frames = 0;               // of the whole render
};

struct FrameShard {
  ShardSpec shard;
  ItemRange frames;         // the frames this shard draws
  std::string output_name;  // the name this shard writes under (a segment's for a video)
  Manifest manifest;
  std::filesystem::path manifest_path;
  std::filesystem::path lock_path;
  std::optional<ShardLock> lock;  // held from start_frame_shard on
};

// Throws ShardError naming --shard when the shard would have no frames.
FrameShard plan_frame_shard(const FrameBatch& batch, const ShardSpec& spec);

// Takes the shard's lock (throws ShardBusy naming a live holder) and writes
// the manifest with "completed": false (call before drawing).
void start_frame_shard(FrameShard& s);
// Adds the files drawn, with their checksums, and marks the manifest completed.
void finish_frame_shard(FrameShard& s, const FrameBatch& batch);

}  // namespace epviz::shard
