#pragma once
// A job file (render_jobs/*.json) as `epviz render` takes it: a single render
// job (job/schema.hpp), a gallery of them (a top-level "jobs" key) or the
// figures of `epviz bench` (a top-level "bench" key). Each format's keys are
// declared once, read strictly (an error names the file, the key path and
// what is allowed: io::BadInput) and listed for the documentation.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "job/document.hpp"
#include "job/schema.hpp"

namespace epviz::job {

// A single job and the file it came from. The output name, when the file
// gives none, is the frame prefix "frame" or, for a video, the file's name.
struct RenderJob {
  std::filesystem::path file;
  SimulationFields simulation;
  std::vector<RunFields> runs;  // a comparison scene's runs over `simulation`; empty: one run
  scene::SceneSettings scene;
  OutputSettings output;
};

// A gallery: several jobs, one still of each tiled into a comparison figure,
// and optionally a video of each. Its jobs' paths are relative to the gallery
// file; its output directory is relative to the current directory.
struct GalleryJob {
  std::filesystem::path file;
  std::vector<RenderJob> jobs;
  int tile_width = 640, tile_height = 360, columns = 3;
  double at = 0.6;                        // which frame to tile, as a fraction of each run
  std::optional<io::VideoFormat> videos;  // a video per job in this format (none: stills only)
  bool grid_video = false;  // also one MP4 of all jobs tiled, frame by frame (grid.mp4)
  std::filesystem::path dir = "out/gallery";
};

// The figures of `epviz bench`: the study is run and its charts are drawn into `dir`.
struct BenchFiguresJob {
  std::filesystem::path file;
  bool quick = false;
  std::vector<std::string> cases;  // empty: all presets
  std::filesystem::path dir = "out/bench";
};

// Exactly one of the three is set.
struct LoadedJob {
  std::optional<RenderJob> single;
  std::optional<GalleryJob> gallery;
  std::optional<BenchFiguresJob> bench;
};
LoadedJob load_job_file(const std::filesystem::path& path);

// Whether `file` is read by another command though it may sit beside render
// jobs: a sweep (*.sweep.json, epviz sweep) or a Poincaré section
// (*.section.json, epviz section). Directories of jobs skip these.
bool is_other_command_file(const std::filesystem::path& file);

// The keys of a gallery and of a bench-figures job, as render_job_keys() lists a single job's.
std::vector<KeyInfo> gallery_job_keys();
std::vector<KeyInfo> bench_job_keys();

}  // namespace epviz::job
