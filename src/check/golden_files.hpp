#pragma once
// A job's goldens on disk: <golden_dir>/frame_NNNN.png and golden.json, and
// how `epviz check --update` writes them.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "check/frame_verdict.hpp"
#include "check/golden_record.hpp"
#include "io/frame_range.hpp"

namespace epviz::check {

// What checking needs to know of one render job.
struct GoldenJob {
  std::string shown;  // the job file as the user named it (or as a gallery lists it)
  std::filesystem::path job_file;
  std::filesystem::path golden_dir;
  int frame_count = 0;      // frames in the job (they set the width of NNNN)
  std::vector<int> frames;  // the frames checked, increasing
  int width = 0, height = 0;

  std::filesystem::path golden_path(int frame) const;
};

// Where a job's goldens go: <golden_root>/<job name>, or <job dir>/golden/<job
// name> when golden_root is empty (the job name is the file name without .json).
std::filesystem::path golden_dir_of(const std::filesystem::path& job_file,
                                    const std::filesystem::path& golden_root);

// The GoldenJob of a job file (`shown` as the user named it) of `frame_count`
// frames of width x height: the frames of `ranges` (frames_to_check), the
// golden folder under `golden_root` (golden_dir_of), its inputs looked at
// (check_golden_inputs). Throws io::BadInput naming the job for a range
// outside it, and as check_golden_inputs does.
GoldenJob golden_job(const std::string& shown, const std::filesystem::path& job_file,
                     const std::filesystem::path& golden_root, int frame_count, int width,
                     int height, std::span<const io::FrameRangeSpec> ranges, bool update);

// Throws io::BadInput when two jobs' goldens would share a folder (job files
// of the same name in different directories, with one --golden root).
void refuse_shared_golden_dirs(std::span<const GoldenJob> jobs);

// Goldens and golden.json come from version control and are hostile input:
// throws io::BadInput naming the file when the golden folder would be under a
// file, when a golden of job.frames is a link or not a regular file (or, when
// comparing, not a PNG), or when golden.json is not a golden record
// (read_golden_record). Called before anything is drawn.
void check_golden_inputs(const GoldenJob& job, bool update);

// A golden PNG's bytes, with the smallest (and slowest) settings: goldens
// live in version control.
std::vector<std::uint8_t> encode_golden_png(const ImageView& image);
void write_golden_png(const std::filesystem::path& path, const ImageView& image);

// Writes pngs[k] (encode_golden_png's bytes) as the golden of job.frames[k]
// (one per frame) and then golden.json. Frames recorded by an earlier update
// whose files are still there stay in the record. Returns the paths written,
// in frame order.
std::vector<std::filesystem::path> write_goldens(const GoldenJob& job,
                                                 std::span<const std::vector<std::uint8_t>> pngs,
                                                 const RenderEnvironment& environment,
                                                 const std::string& epviz_version);

}  // namespace epviz::check
