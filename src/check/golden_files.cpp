#include "check/golden_files.hpp"

#include <map>
#include <set>
#include <stdexcept>

#include "check/frame_choice.hpp"
#include "check/golden_record.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/frame_names.hpp"
#include "io/png_reader.hpp"
#include "io/png_writer.hpp"
#include "io/printable.hpp"

namespace epviz::check {

namespace fs = std::filesystem;

fs::path GoldenJob::golden_path(int frame) const {
  return golden_dir / io::frame_file_name(frame, frame_count);
}

fs::path golden_dir_of(const fs::path& job_file, const fs::path& golden_root) {
  const fs::path name = job_file.stem();
  return golden_root.empty() ? job_file.parent_path() / "golden" / name : golden_root / name;
}

namespace {

[[noreturn]] void refuse(const fs::path& path, const std::string& what) {
  throw io::BadInput(io::printable(path.string(), 200) + ": " + what);
}

// A golden may be missing or a regular file; anything else in a golden folder
// (a link git checked out, a FIFO, a directory) is refused before reading or
// writing through it.
bool golden_file_exists(const fs::path& path) {
  std::error_code ec;
  const auto type = fs::symlink_status(path, ec).type();
  if (type == fs::file_type::not_found) return false;
  if (type == fs::file_type::symlink)
    refuse(path, "a golden is a symbolic link; goldens must be regular files");
  if (type != fs::file_type::regular) refuse(path, "a golden is not a regular file");
  return true;
}

// The golden folder, or the nearest of its parents that exists, must be a directory.
void check_golden_folder(const fs::path& dir) {
  for (fs::path p = dir; !p.empty(); p = p.parent_path()) {
    std::error_code ec;
    const auto type = fs::status(p, ec).type();
    if (type == fs::file_type::directory) return;
    if (type != fs::file_type::not_found)
      refuse(p, "the golden folder " + io::printable(dir.string(), 200) +
                    " would be under this, which is not a directory");
    if (p == p.parent_path()) return;
  }
}

}  // namespace

void check_golden_inputs(const GoldenJob& job, bool update) {
  check_golden_folder(job.golden_dir);
  for (const int f : job.frames) {
    const fs::path path = job.golden_path(f);
    if (golden_file_exists(path) && !update && !io::read_png_size(path))
      refuse(path, "a damaged golden: not a PNG; re-baseline it with --update");
  }
  // --update keeps the recorded frames whose files are there: look at them now.
  if (const auto rec = read_golden_record(job.golden_dir / "golden.json"))
    for (const int f : rec->frames)
      if (f < job.frame_count) golden_file_exists(job.golden_path(f));
}

GoldenJob golden_job(const std::string& shown, const fs::path& job_file,
                     const fs::path& golden_root, int frame_count, int width, int height,
                     std::span<const io::FrameRangeSpec> ranges, bool update) {
  GoldenJob g;
  try {
    g.frames = frames_to_check(ranges, frame_count);
  } catch (const io::FrameRangeError& e) {
    throw io::BadInput(shown + ": " + e.what());
  }
  g.golden_dir = golden_dir_of(job_file, golden_root);
  g.shown = shown;
  g.job_file = job_file;
  g.frame_count = frame_count;
  g.width = width;
  g.height = height;
  check_golden_inputs(g, update);
  return g;
}

void refuse_shared_golden_dirs(std::span<const GoldenJob> jobs) {
  std::map<fs::path, std::string> owner;
  for (const auto& g : jobs)
    if (auto [it, fresh] = owner.emplace(fs::weakly_canonical(g.golden_dir), g.shown); !fresh)
      throw io::BadInput(g.shown + ": its goldens would share " + g.golden_dir.string() + " with " +
                         it->second + " (jobs need distinct file names)");
}

std::vector<std::uint8_t> encode_golden_png(const ImageView& image) {
  return io::encode_png_rgba(image.width, image.height, image.rgba,
                             {.compression_level = 9, .filter = -1});
}

void write_golden_png(const fs::path& path, const ImageView& image) {
  const auto bytes = encode_golden_png(image);
  io::write_file_atomically(path, std::as_bytes(std::span(bytes)));
}

std::vector<fs::path> write_goldens(const GoldenJob& job,
                                    std::span<const std::vector<std::uint8_t>> pngs,
                                    const RenderEnvironment& environment,
                                    const std::string& epviz_version) {
  if (pngs.size() != job.frames.size())
    throw std::invalid_argument(job.shown + ": " + std::to_string(pngs.size()) + " images for " +
                                std::to_string(job.frames.size()) + " frames");
  if (std::error_code ec; (fs::create_directories(job.golden_dir, ec), ec))
    throw io::FileWriteError("cannot create the golden folder '" +
                             io::printable(job.golden_dir.string(), 200) + "': " + ec.message());
  std::vector<fs::path> written;
  for (std::size_t k = 0; k < pngs.size(); ++k) {
    written.push_back(job.golden_path(job.frames[k]));
    golden_file_exists(written.back());  // never write through a link
    io::write_file_atomically(written.back(), std::as_bytes(std::span(pngs[k])));
  }
  GoldenRecord rec;
  rec.epviz_version = epviz_version;
  rec.gl_renderer = environment.gl_renderer;
  rec.gl_version = environment.gl_version;
  rec.font_file = environment.font_file;
  rec.font_hash = environment.font_hash;
  rec.job_file = job.job_file.filename().string();
  rec.job_hash = file_hash(job.job_file);
  const fs::path record = job.golden_dir / "golden.json";
  golden_file_exists(record);
  std::set<int> frames(job.frames.begin(), job.frames.end());
  if (auto old = read_golden_record(record))
    for (const int f : old->frames)
      if (f < job.frame_count && golden_file_exists(job.golden_path(f))) frames.insert(f);
  rec.frames.assign(frames.begin(), frames.end());
  rec.width = job.width;
  rec.height = job.height;
  io::write_file_atomically(record, to_json_text(rec));
  return written;
}

}  // namespace epviz::check
