#include "check/golden_files.hpp"

#include <set>
#include <stdexcept>

#include "check/golden_record.hpp"
#include "io/atomic_file.hpp"
#include "io/frame_names.hpp"
#include "io/png_writer.hpp"

namespace epviz::check {

namespace fs = std::filesystem;

fs::path GoldenJob::golden_path(int frame) const {
  return golden_dir / io::frame_file_name(frame, frame_count);
}

fs::path golden_dir_of(const fs::path& job_file, const fs::path& golden_root) {
  const fs::path name = job_file.stem();
  return golden_root.empty() ? job_file.parent_path() / "golden" / name : golden_root / name;
}

void write_golden_png(const fs::path& path, const ImageView& image) {
  io::write_png_rgba(path, image.width, image.height, image.rgba,
                     {.compression_level = 9, .filter = -1});
}

std::vector<fs::path> write_goldens(const GoldenJob& job, std::span<const ImageView> images,
                                    const RendererInfo& renderer,
                                    const std::string& epviz_version) {
  if (images.size() != job.frames.size())
    throw std::invalid_argument(job.shown + ": " + std::to_string(images.size()) + " images for " +
                                std::to_string(job.frames.size()) + " frames");
  fs::create_directories(job.golden_dir);
  std::vector<fs::path> written;
  for (std::size_t k = 0; k < images.size(); ++k) {
    written.push_back(job.golden_path(job.frames[k]));
    write_golden_png(written.back(), images[k]);
  }
  GoldenRecord rec;
  rec.epviz_version = epviz_version;
  rec.gl_renderer = renderer.renderer;
  rec.gl_version = renderer.version;
  rec.job_file = job.job_file.filename().string();
  rec.job_hash = job_file_hash(job.job_file);
  const fs::path record = job.golden_dir / "golden.json";
  std::set<int> frames(job.frames.begin(), job.frames.end());
  if (auto old = read_golden_record(record))
    for (const int f : old->frames)
      if (f < job.frame_count && fs::exists(job.golden_path(f))) frames.insert(f);
  rec.frames.assign(frames.begin(), frames.end());
  rec.width = job.width;
  rec.height = job.height;
  io::write_file_atomically(record, to_json_text(rec));
  return written;
}

}  // namespace epviz::check
