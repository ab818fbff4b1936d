#include "shard/frame_shard.hpp"

#include "io/frame_names.hpp"

namespace epviz::shard {

namespace fs = std::filesystem;

FrameShard plan_frame_shard(const FrameBatch& batch, const ShardSpec& spec) {
  FrameShard s;
  s.shard = spec;
  s.frames = shard_range(batch.frames, spec);
  if (s.frames.size() < 1)
    throw ShardError("--shard: " + std::to_string(spec.count) + " shards of a job of " +
                     std::to_string(batch.frames) + " frames leave shard " +
                     std::to_string(spec.index) + " without frames; use at most " +
                     std::to_string(batch.frames) + " shards");
  const bool video = !batch.video_extension.empty();
  s.output_name = video ? batch.name + "." + shard_tag(spec) : batch.name;

  s.manifest = shard_manifest("render", batch.origin, spec, s.frames, batch.frames,
                              video ? batch.name + batch.video_extension : "");
  const std::string stem = (batch.name.empty() ? "frames" : batch.name) + (video ? "" : "_png");
  s.manifest_path = batch.dir / manifest_name(stem, spec);
  s.lock_path = batch.dir / lock_name(stem, spec);
  return s;
}

void start_frame_shard(FrameShard& s) {
  fs::create_directories(s.manifest_path.parent_path());
  s.lock.emplace(s.lock_path);
  write_manifest(s.manifest_path, s.manifest);
}

void finish_frame_shard(FrameShard& s, const FrameBatch& batch) {
  const fs::path& dir = batch.dir;
  if (batch.video_extension.empty()) {
    for (long i = s.frames.first; i < s.frames.end; ++i)
      add_file(s.manifest, dir,
               dir / io::frame_file_name(int(i), batch.frames, batch.name + "_", ".png"));
  } else {
    add_file(s.manifest, dir, dir / (s.output_name + batch.video_extension));
  }
  s.manifest.completed = true;
  write_manifest(s.manifest_path, s.manifest);
}

}  // namespace epviz::shard
