#include "shard/batch.hpp"

#include <algorithm>

#include "io/bad_input.hpp"
#include "io/printable.hpp"

namespace epviz::shard {

namespace fs = std::filesystem;

std::string batch_name(const Batch& b) {
  const auto& m = b.shards.begin()->second;
  return m.kind + " " + m.source + " (" + std::to_string(b.count) + " shards)";
}

std::vector<Batch> read_batches(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename().string().ends_with(manifest_suffix))
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::map<std::string, Batch> by_key;
  for (const auto& f : files) {
    Manifest m = read_manifest(f);
    auto& b = by_key[m.kind + "/" + m.hash];
    b.kind = m.kind;
    b.hash = m.hash;
    const std::string name = io::printable(f.string(), 300);
    if (b.count && b.count != m.shard.count)
      throw io::BadInput(name + ": shard of " + std::to_string(m.shard.count) +
                         " while other shards of the same batch say " + std::to_string(b.count) +
                         "; remove the manifests of the old split");
    // Shards of one batch that disagree on these would leave items to no shard
    // or join into two outputs.
    if (!b.shards.empty()) {
      const auto& other = b.shards.begin()->second;
      if (other.total != m.total)
        throw io::BadInput(name + ": key 'total': " + std::to_string(m.total) +
                           " while other shards of the same batch say " +
                           std::to_string(other.total));
      if (other.output != m.output)
        throw io::BadInput(name + ": key 'output': '" + io::printable(m.output) +
                           "' while other shards of the same batch say '" +
                           io::printable(other.output) + "'");
    }
    b.count = m.shard.count;
    b.shards[m.shard.index] = std::move(m);
  }
  std::vector<Batch> out;
  for (auto& [key, b] : by_key) out.push_back(std::move(b));
  return out;
}

void check_batch(Batch& b, const fs::path& dir) {
  const auto& any = b.shards.begin()->second;
  for (long i = 0; i < b.count; ++i) {
    auto it = b.shards.find(i);
    std::vector<std::string> found;
    if (it != b.shards.end() && it->second.completed) {
      found = file_problems(it->second, dir);
      if (found.empty()) continue;
    }
    b.incomplete.push_back(i);
    if (b.problems.size() >= max_listed_problems) {  // counted without building its lines
      ++b.unlisted;
      continue;
    }
    if (it == b.shards.end())
      found.push_back("missing (no manifest in " + io::printable(dir.string(), 300) + ")");
    else if (!it->second.completed)
      found.push_back("not completed (killed, failed or still running)");
    const std::string tag = "shard " + std::to_string(i) + "/" + std::to_string(b.count);
    const std::string redo = "; run: " + rerun_command(any, i);
    for (const auto& p : found) b.problems.push_back(tag + ": " + p + redo);
  }
}

}  // namespace epviz::shard
