#include "shard/batch.hpp"

#include <algorithm>

#include "io/bad_input.hpp"

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
    if (b.count && b.count != m.shard.count)
      throw io::BadInput(f.string() + ": shard of " + std::to_string(m.shard.count) +
                         " while other shards of the same batch say " + std::to_string(b.count) +
                         "; remove the manifests of the old split");
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
    const std::string tag = "shard " + std::to_string(i) + "/" + std::to_string(b.count);
    const std::string redo = "; run: " + rerun_command(any, i);
    auto it = b.shards.find(i);
    if (it == b.shards.end()) {
      b.problems.push_back(tag + ": missing (no manifest in " + dir.string() + ")" + redo);
      continue;
    }
    if (!it->second.completed) {
      b.problems.push_back(tag + ": not completed (killed, failed or still running)" + redo);
      continue;
    }
    for (const auto& p : file_problems(it->second, dir))
      b.problems.push_back(tag + ": " + p + redo);
  }
}

}  // namespace epviz::shard
