#include "section/section_merge.hpp"

#include <fstream>
#include <sstream>

#include "io/bad_input.hpp"
#include "io/printable.hpp"
#include "section/section_csv.hpp"

namespace epviz::section {

namespace fs = std::filesystem;

namespace {

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw io::BadInput(path.string() + ": cannot be read");
  return text.str();
}

}  // namespace

MergedSection read_section_shards(const shard::Batch& b, const fs::path& dir,
                                  const fs::path& out_dir) {
  const auto& any = b.shards.begin()->second;
  MergedSection m;
  try {
    m.job = read_section_job(any.source);
  } catch (const std::exception& e) {
    throw io::BadInput(any.source + ": the section file of these shards cannot be read (" +
                       e.what() + "); the merge needs it to name the runs and draw the pictures");
  }
  if (m.job.hash != b.hash)
    throw io::BadInput(any.source + ": changed since its shards ran (hash " + m.job.hash +
                       ", the shards' " + b.hash + "); restore it or run the shards again");
  const long runs = any.total;
  if (runs % long(m.job.methods.size()) != 0)
    throw io::BadInput(any.source + ": its shards ran " + std::to_string(runs) +
                       " runs, which its methods do not divide");
  const std::size_t starts = std::size_t(runs) / m.job.methods.size();
  m.results.resize(std::size_t(runs));
  for (long r = 0; r < runs; ++r) {
    const SectionRun run = section_run_of(r, starts);
    m.results[std::size_t(r)].orbit = int(run.start) + 1;
    m.results[std::size_t(r)].method = run.method;
  }
  const std::string header = crossings_csv_header(m.job);
  m.csv_text = header;
  for (const auto& [index, shard] : b.shards) {
    for (const auto& f : shard.files) {
      const fs::path path = dir / f.path;
      const std::string text = file_text(path);
      for (auto& r : crossings_from_csv(m.job, text, io::printable(path.string(), 300))) {
        const long run = long(r.method * starts) + r.orbit - 1;
        if (run < shard.items.first || run >= shard.items.end)
          throw io::BadInput(path.string() + ": orbit " + std::to_string(r.orbit) +
                             " is not one of shard " + std::to_string(index) + "'s runs");
        m.results[std::size_t(run)].crossings = std::move(r.crossings);
      }
      m.csv_text.append(text, header.size());
    }
  }
  const auto into_out = [&](std::string& path) {
    if (!path.empty()) path = (out_dir / fs::path(path).filename()).string();
  };
  m.job.csv = (out_dir / any.output).string();
  into_out(m.job.png);
  into_out(m.job.svg);
  into_out(m.job.pdf);
  return m;
}

}  // namespace epviz::section
