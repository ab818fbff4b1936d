#pragma once
// The jobs epviz ships: render_jobs/ in the first data directory that holds
// one (io/data_dir.hpp: the installed share/epviz, $EPVIZ_DATA_DIR, then the
// source tree a build tree came from). `epviz render --list-jobs` lists them
// and `epviz render NAME` takes one by its name; the sections
// (NAME.section.json) and sweeps (NAME.sweep.json) there are listed too, and
// `epviz section NAME` and `epviz sweep NAME` take them by name.
#include <filesystem>
#include <string>
#include <vector>

namespace epviz::job {

// Which command a shipped file is for, by its name's ending.
enum class ShippedKind { render, section, sweep };

struct ShippedJob {
  std::string name;  // the file's name without ".json": what `epviz render` takes
  std::filesystem::path file;
  std::string about;  // "render job: case kovalevskaya, png", "gallery of 7 jobs", ...
};

// The shipped jobs' directory; empty when no data directory has one.
std::filesystem::path shipped_jobs_dir();

// The jobs `epviz render` takes in `dir` (its *.json files but the sweeps,
// *.sweep.json, which are `epviz sweep`'s), by name. Throws io::BadInput
// naming the file when one is not a job.
std::vector<ShippedJob> shipped_jobs(const std::filesystem::path& dir);

// The sections or sweeps in `dir` (kind section or sweep), by name: the
// name is the file's without ".section.json" or ".sweep.json"; `about` names
// the case when the file gives one. Not parsed further: the command that
// runs one reads it strictly.
std::vector<ShippedJob> shipped_files(const std::filesystem::path& dir, ShippedKind kind);

// What --list-jobs prints: the directory, then one line per job, per section
// and per sweep, each group under the command that takes it.
std::string shipped_jobs_text(const std::filesystem::path& dir);

// The job file `arg` names: itself when it is a path (it exists, or holds a
// '/'), else the shipped job of that name (with or without ".json") in `dir`.
// Throws io::BadInput when a bare name is neither a file nor a shipped job.
// With kind section or sweep: the shipped NAME.section.json or
// NAME.sweep.json.
std::filesystem::path job_file_named(const std::string& arg, const std::filesystem::path& dir,
                                     ShippedKind kind = ShippedKind::render);

}  // namespace epviz::job
