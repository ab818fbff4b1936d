// A section file's bytes through what `epviz section` does with them before
// any orbit runs: the strict reader, the check of its output paths and the
// orbits' starts (a level's states, or the explicit ones checked against the
// case's conditions). Bad input must end in the error a user sees (exit 2),
// never in a crash or another exception; what is accepted must be a job the
// run can take as it is.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "io/bad_input.hpp"
#include "section/section_job.hpp"

namespace {

namespace fs = std::filesystem;
using namespace epviz;

// One file per fuzzing process, rewritten for each input (the reader takes a
// path, as the command does) and removed when the fuzzer exits. Never
// destroyed: the exit hook may run after the statics' destructors.
const fs::path& job_file() {
  static const fs::path& file = *new fs::path(
      fs::temp_directory_path() / ("epviz-fuzz-section-" + std::to_string(::getpid()) + ".json"));
  static const bool removed_at_exit = std::atexit([] {
                                        std::error_code ec;
                                        fs::remove(job_file(), ec);
                                      }) == 0;
  (void)removed_at_exit;
  return file;
}

// What the run relies on without checking again (docs/sections.md's ranges).
void check_accepted(const section::SectionJob& job) {
  if (job.orbits < 1 || job.crossings < 1) std::abort();
  if (job.methods.empty() || job.methods.size() > section::kMaxSectionMethods) std::abort();
  if (double(job.orbits) * job.crossings * double(job.methods.size()) > 1e7) std::abort();
  if (job.level.has_value() == !job.states.empty()) std::abort();
  if (!job.level && std::size_t(job.orbits) != job.states.size()) std::abort();
  if (!(job.t_end > 0) || !(job.max_drift > 0)) std::abort();
  for (const auto& m : job.methods)
    if (!(m.tol > 0) || !(m.step > 0)) std::abort();
  if (job.csv.empty()) std::abort();
}

void read_section_bytes(const std::uint8_t* data, std::size_t size) {
  {
    // A new file each time, not the old one truncated: ext4 writes a file
    // truncated and rewritten out to disk when it is closed (auto_da_alloc),
    // which took most of each run's time.
    std::error_code ec;
    fs::remove(job_file(), ec);
    std::ofstream out(job_file(), std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  const section::SectionJob job = section::read_section_job(job_file());
  check_accepted(job);
  section::check_outputs(job);
  // Outputs that pass the check are distinct files: one would overwrite another.
  const std::string outputs[] = {job.csv, job.png, job.svg};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (!outputs[i].empty() && outputs[i] != "-" && outputs[i] == outputs[j]) std::abort();
  const auto starts = section::section_starts(job);
  if (starts.empty() || starts.size() > std::size_t(job.orbits)) std::abort();
  for (const auto& s : starts)
    if (!s.omega.allFinite() || !(std::abs(s.gamma.norm() - 1.0) <= 1e-9)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    read_section_bytes(data, size);
  } catch (const io::BadInput&) {
  }
  return 0;
}
