#include "job/shipped_jobs.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "io/bad_input.hpp"
#include "io/data_dir.hpp"
#include "io/json_reader.hpp"
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

std::string_view suffix_of(ShippedKind kind) {
  return kind == ShippedKind::section ? ".section.json" : ".sweep.json";
}

std::string_view command_of(ShippedKind kind) {
  switch (kind) {
    case ShippedKind::render: return "render";
    case ShippedKind::section: return "section";
    case ShippedKind::sweep: return "sweep";
  }
  return "render";
}

// "case kovalevskaya", read from the file's "case" (a sweep's under
// "simulation"), or a plain word when the file gives none or cannot be read.
std::string about_file(const fs::path& file, ShippedKind kind) {
  std::string what = kind == ShippedKind::section ? "Poincare section" : "parameter sweep";
  try {
    const nlohmann::json doc = io::read_json_file(file);
    const nlohmann::json* holder = &doc;
    if (kind == ShippedKind::sweep && doc.contains("simulation")) holder = &doc["simulation"];
    if (holder->is_object() && holder->contains("case") && (*holder)["case"].is_string())
      what += ": case " + io::printable((*holder)["case"].get<std::string>());
  } catch (const io::BadInput&) {
    what += " (not readable: the command names the problem)";
  }
  return what;
}

void append_group(std::string& text, const std::vector<ShippedJob>& jobs, ShippedKind kind,
                  std::size_t width) {
  if (jobs.empty()) return;
  text += "epviz ";
  text += command_of(kind);
  text += " NAME:\n";
  for (const auto& j : jobs)
    text += "  " + j.name + std::string(width - j.name.size() + 2, ' ') + j.about + "\n";
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

std::vector<ShippedJob> shipped_files(const fs::path& dir, ShippedKind kind) {
  std::vector<ShippedJob> files;
  const std::string_view suffix = suffix_of(kind);
  std::error_code error;
  for (const auto& e : fs::directory_iterator(dir, error)) {
    const std::string name = e.path().filename().string();
    if (!e.is_regular_file() || name.size() <= suffix.size() || !name.ends_with(suffix)) continue;
    files.push_back(
        {name.substr(0, name.size() - suffix.size()), e.path(), about_file(e.path(), kind)});
  }
  std::sort(files.begin(), files.end(),
            [](const ShippedJob& a, const ShippedJob& b) { return a.name < b.name; });
  return files;
}

std::string shipped_jobs_text(const fs::path& dir) {
  if (dir.empty())
    return "no shipped jobs: no data directory holds render_jobs/ (install epviz, or set "
           "EPVIZ_DATA_DIR)\n";
  const auto jobs = shipped_jobs(dir);
  const auto sections = shipped_files(dir, ShippedKind::section);
  const auto sweeps = shipped_files(dir, ShippedKind::sweep);
  std::size_t width = 0;
  for (const auto* group : {&jobs, &sections, &sweeps})
    for (const auto& j : *group) width = std::max(width, j.name.size());
  std::string text = "shipped jobs in " + dir.string() + ":\n";
  append_group(text, jobs, ShippedKind::render, width);
  append_group(text, sections, ShippedKind::section, width);
  append_group(text, sweeps, ShippedKind::sweep, width);
  return text;
}

fs::path job_file_named(const std::string& arg, const fs::path& dir, ShippedKind kind) {
  std::error_code error;
  if (arg.find('/') != std::string::npos || fs::exists(arg, error)) return arg;
  if (!dir.empty()) {
    if (kind == ShippedKind::render) {
      const std::string name =
          fs::path(arg).extension() == ".json" ? fs::path(arg).stem().string() : arg;
      const auto file = dir / (name + ".json");
      if (!is_other_command_file(file) && fs::is_regular_file(file, error)) return file;
    } else {
      const std::string suffix(suffix_of(kind));
      const std::string name =
          arg.ends_with(suffix) ? arg.substr(0, arg.size() - suffix.size()) : arg;
      const auto file = dir / (name + suffix);
      if (fs::is_regular_file(file, error)) return file;
    }
  }
  const std::string what = kind == ShippedKind::render    ? "job file"
                           : kind == ShippedKind::section ? "section file"
                                                          : "sweep file";
  throw io::BadInput(io::quoted(arg, 200) + ": no such " + what + ", nor a shipped " +
                     std::string(command_of(kind)) +
                     " of that name (epviz render --list-jobs lists them)");
}

}  // namespace epviz::job
