#include "job/job_list.hpp"

#include <algorithm>
#include <set>

#include "io/bad_input.hpp"

namespace epviz::job {

namespace fs = std::filesystem;

std::vector<std::pair<RenderJob, std::string>> render_jobs_in(
    const std::vector<std::string>& args) {
  std::vector<std::pair<RenderJob, std::string>> out;
  std::set<fs::path> seen;
  auto add = [&](RenderJob job, const std::string& shown) {
    const auto key = fs::weakly_canonical(job.file);
    if (seen.insert(key).second) out.emplace_back(std::move(job), shown);
  };
  auto add_loaded = [&](const fs::path& file, bool from_dir) {
    auto loaded = load_job_file(file);
    if (loaded.bench) {
      if (from_dir) return;
      throw io::BadInput(file.string() +
                         ": a bench-figures job has no frames to check (allowed: a render job, a "
                         "gallery or a directory of them)");
    }
    if (loaded.gallery)
      for (auto& j : loaded.gallery->jobs) add(j, j.file.string());
    else
      add(std::move(*loaded.single), file.string());
  };
  for (const auto& arg : args) {
    if (fs::is_directory(arg)) {
      std::vector<fs::path> files;
      for (const auto& e : fs::directory_iterator(arg))
        if (e.is_regular_file() && e.path().extension() == ".json" &&
            !is_other_command_file(e.path()))
          files.push_back(e.path());
      std::sort(files.begin(), files.end());
      if (files.empty()) throw io::BadInput(arg + ": no render jobs (*.json) in this directory");
      for (const auto& f : files) add_loaded(f, true);
    } else {
      add_loaded(arg, false);
    }
  }
  return out;
}

}  // namespace epviz::job
