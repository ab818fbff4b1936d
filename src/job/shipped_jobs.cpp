#include "job/shipped_jobs.hpp"

#include <algorithm>

#include "io/bad_input.hpp"
#include "io/data_dir.hpp"
#include "io/printable.hpp"
#include "job/job_file.hpp"

namespace epviz::job {

namespace fs = std::filesystem;

namespace {

std::string about(const LoadedJob& loaded) {
  if (loaded.bench)
    return std::string("figures of epviz bench") + (loaded.bench->quick ? " --quick" : "");
  if (loaded.gallery) return "gallery of " + std::to_string(loaded.gallery->jobs.size()) + " jobs";
  const auto& job = *loaded.single;
  std::string s = "render job: case ";
  s += job.simulation.case_name ? *job.simulation.case_name : "custom";
  if (!job.runs.empty()) s += ", " + std::to_string(job.runs.size()) + " runs compared";
  s += ", ";
  s += output_format_name(job.output.video);
  return s;
}

}  // namespace

fs::path shipped_jobs_dir() { return io::find_data_path("render_jobs"); }

std::vector<ShippedJob> shipped_jobs(const fs::path& dir) {
  std::vector<ShippedJob> jobs;
  std::error_code error;
  for (const auto& e : fs::directory_iterator(dir, error)) {
    const auto& file = e.path();
    if (!e.is_regular_file() || file.extension() != ".json" || is_other_command_file(file))
      continue;
    jobs.push_back({file.stem().string(), file, about(load_job_file(file))});
  }
  std::sort(jobs.begin(), jobs.end(),
            [](const ShippedJob& a, const ShippedJob& b) { return a.name < b.name; });
  return jobs;
}

std::string shipped_jobs_text(const fs::path& dir) {
  if (dir.empty())
    return "no shipped jobs: no data directory holds render_jobs/ (install epviz, or set "
           "EPVIZ_DATA_DIR)\n";
  const auto jobs = shipped_jobs(dir);
  std::size_t width = 0;
  for (const auto& j : jobs) width = std::max(width, j.name.size());
  std::string text = "shipped jobs in " + dir.string() + " (epviz render NAME):\n";
  for (const auto& j : jobs)
    text += "  " + j.name + std::string(width - j.name.size() + 2, ' ') + j.about + "\n";
  return text;
}

fs::path job_file_named(const std::string& arg, const fs::path& dir) {
  std::error_code error;
  if (arg.find('/') != std::string::npos || fs::exists(arg, error)) return arg;
  const std::string name =
      fs::path(arg).extension() == ".json" ? fs::path(arg).stem().string() : arg;
  if (!dir.empty()) {
    const auto file = dir / (name + ".json");
    if (!is_other_command_file(file) && fs::is_regular_file(file, error)) return file;
  }
  throw io::BadInput(io::quoted(arg, 200) +
                     ": no such job file, nor a shipped job of that name (epviz render "
                     "--list-jobs lists them)");
}

}  // namespace epviz::job
