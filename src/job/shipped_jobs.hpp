#pragma once
// The jobs epviz ships: render_jobs/ in the first data directory that holds
// one (io/data_dir.hpp: the installed share/epviz, $EPVIZ_DATA_DIR, then the
// source tree a build tree came from). `epviz render --list-jobs` lists them
// and `epviz render NAME` takes one by its name.
#include <filesystem>
#include <string>
#include <vector>

namespace epviz::job {

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

// What --list-jobs prints: the directory, then one line per job.
std::string shipped_jobs_text(const std::filesystem::path& dir);

// The job file `arg` names: itself when it is a path (it exists, or holds a
// '/'), else the shipped job of that name (with or without ".json") in `dir`.
// Throws io::BadInput when a bare name is neither a file nor a shipped job.
std::filesystem::path job_file_named(const std::string& arg, const std::filesystem::path& dir);

}  // namespace epviz::job
