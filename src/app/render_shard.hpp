#pragma once
// `epviz render JOB --shard I/N`: shard I draws a contiguous range of the
// job's frames. Every shard integrates from t = 0 through the frames before
// its range (as --frames does), so trails and states, and thus the PNG bytes,
// are those of the unsharded render. PNG frames keep their absolute numbers;
// a video shard writes a segment "<name>.shard-I-of-N.<ext>" that `epviz
// merge` joins. Each shard writes a manifest (shard/manifest.hpp) beside its output.
#include <filesystem>
#include <optional>
#include <string>

#include "app/render_job.hpp"
#include "io/frame_range.hpp"
#include "shard/manifest.hpp"

namespace epviz::app {

struct RenderShard {
  shard::ShardSpec shard;
  io::FrameRange range;     // the frames this shard draws
  std::string output_name;  // the job's output.name for this shard (a segment's for video)
  shard::Manifest manifest;
  std::filesystem::path manifest_path;
  int frame_count = 0;
};

// nullopt when no shard is asked for (neither option nor array-job
// environment). `job` is the job as it will be drawn (options applied).
// Throws UsageError for a bad shard or one combined with --frames.
std::optional<RenderShard> plan_render_shard(const std::string& shard_option,
                                             const std::string& shard_count_option,
                                             const std::string& frames_option, const RenderJob& job,
                                             int frame_count);

// Writes the manifest with "completed": false (call before drawing).
void start_render_shard(const RenderShard& s);
// Adds the files drawn, with their checksums, and marks the manifest completed.
void finish_render_shard(RenderShard& s, const RenderJob& job);

}  // namespace epviz::app
