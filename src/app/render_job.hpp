#pragma once
// Render jobs (render_jobs/*.json): what to simulate, what to draw and where
// to write it. Every error names the file, the key path and what is allowed.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/simulation_fields.hpp"
#include "job/document.hpp"
#include "scene/settings.hpp"

namespace epviz::app {

// The keys of a single job and their reading live in job/schema.hpp.
using job::output_format_from_name;
using job::output_format_name;
using job::OutputFormat;
using job::OutputSettings;

struct RenderJob {
  std::filesystem::path file;
  SimulationFields simulation;
  std::vector<job::RunFields> runs;  // a comparison scene's runs over `simulation`; empty: one run
  scene::SceneSettings scene;
  OutputSettings output;
};

// A gallery: several jobs, one still of each tiled into a comparison figure,
// and optionally a video of each.
struct GalleryJob {
  std::filesystem::path file;
  std::vector<RenderJob> jobs;
  int tile_width = 640, tile_height = 360, columns = 3;
  double at = 0.6;                     // which frame to tile, as a fraction of each run
  std::optional<OutputFormat> videos;  // a video per job in this format (none: stills only)
  bool grid_video = false;             // also one MP4 of all jobs tiled, frame by frame (grid.mp4)
  std::filesystem::path dir = "out/gallery";
};

// The figures of `epviz bench` (a top-level "bench" key): the study is run and
// its charts are drawn into `dir`.
struct BenchFiguresJob {
  std::filesystem::path file;
  bool quick = false;
  std::vector<std::string> cases;  // empty: all presets
  std::filesystem::path dir = "out/bench";
};

// A single job, a gallery (a top-level "jobs" key) or the bench figures. Relative job
// paths inside a gallery are relative to the gallery file; relative output
// directories are relative to the current directory.
struct LoadedJob {
  std::optional<RenderJob> single;
  std::optional<GalleryJob> gallery;
  std::optional<BenchFiguresJob> bench;
};
LoadedJob load_render_job(const std::filesystem::path& path);

}  // namespace epviz::app
