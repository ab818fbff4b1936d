#include "app/render_shard.hpp"

#include "app/shard_options.hpp"
#include "app/usage_error.hpp"
#include "io/frame_names.hpp"
#include "io/video_writer.hpp"
#include "job/schema.hpp"
#include "shard/checksum.hpp"

namespace epviz::app {

namespace fs = std::filesystem;

namespace {

std::string extension(const RenderJob& job) {
  const auto fmt = io::parse_video_format(output_format_name(job.output.format));
  return fmt ? std::string(io::video_format_extension(*fmt)) : ".png";
}

}  // namespace

std::optional<RenderShard> plan_render_shard(const std::string& shard_option,
                                             const std::string& shard_count_option,
                                             const std::string& frames_option, const RenderJob& job,
                                             int frame_count) {
  const auto spec = shard_from_options(shard_option, shard_count_option);
  if (!spec) return std::nullopt;
  if (!frames_option.empty())
    throw UsageError("--frames: a shard's frames follow from --shard; give one of them");
  RenderShard s;
  s.shard = *spec;
  s.frame_count = frame_count;
  const auto items = shard::shard_range(frame_count, *spec);
  if (items.size() < 1)
    throw UsageError("--shard: " + std::to_string(spec->count) + " shards of a job of " +
                     std::to_string(frame_count) + " frames leave shard " +
                     std::to_string(spec->index) + " without frames; use at most " +
                     std::to_string(frame_count) + " shards");
  s.range = {int(items.first), int(items.end - 1)};
  const bool video = job.output.format != OutputFormat::png;
  s.output_name = video ? job.output.name + "." + shard::shard_tag(*spec) : job.output.name;

  // The batch is the job as drawn: its canonical keys with the options applied.
  job::JobDocument doc{job.simulation, job.runs, job.scene, job.output};
  doc.output.dir = "";
  auto& m = s.manifest;
  m.kind = "render";
  m.source = fs::absolute(job.file).lexically_normal().string();
  m.hash = shard::checksum_of(job::write_job(doc).dump());
  m.shard = *spec;
  m.items = items;
  m.total = frame_count;
  const std::string dir = fs::absolute(job.output.dir).lexically_normal().string();
  m.command = {"epviz",
               "render",
               m.source,
               "--out",
               dir,
               "--width",
               std::to_string(job.scene.width),
               "--height",
               std::to_string(job.scene.height),
               "--format",
               std::string(output_format_name(job.output.format))};
  m.output = video ? job.output.name + extension(job) : "";
  s.manifest_path =
      job.output.dir /
      shard::manifest_name(
          (job.output.name.empty() ? "frames" : job.output.name) + (video ? "" : "_png"), *spec);
  return s;
}

void start_render_shard(const RenderShard& s) {
  fs::create_directories(s.manifest_path.parent_path());
  shard::write_manifest(s.manifest_path, s.manifest);
}

void finish_render_shard(RenderShard& s, const RenderJob& job) {
  const fs::path& dir = job.output.dir;
  if (job.output.format == OutputFormat::png) {
    for (int i = s.range.first; i <= s.range.last; ++i)
      shard::add_file(s.manifest, dir,
                      dir / io::frame_file_name(i, s.frame_count, job.output.name + "_", ".png"));
  } else {
    shard::add_file(s.manifest, dir, dir / (s.output_name + extension(job)));
  }
  s.manifest.completed = true;
  shard::write_manifest(s.manifest_path, s.manifest);
}

}  // namespace epviz::app
