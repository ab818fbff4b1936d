#include "shard/batch.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "io/bad_input.hpp"
#include "io/printable.hpp"
#include "shard/shard_lock.hpp"

namespace epviz::shard {

namespace fs = std::filesystem;

std::string batch_name(const Batch& b) {
  const auto& m = b.shards.begin()->second;
  return m.kind + " " + io::printable(m.source, 200) + " (" + std::to_string(b.count) + " shards)";
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
    if (b.stem.empty()) b.stem = manifest_stem(f.filename().string(), m.shard);
    b.shards[m.shard.index] = std::move(m);
  }
  std::vector<Batch> out;
  for (auto& [key, b] : by_key) out.push_back(std::move(b));
  // Two batches (two sweeps, or one sweep split twice) that merge into one
  // name: the later's rows would replace the earlier's. Neither is merged.
  std::map<std::string, const Batch*> by_output;
  for (const auto& b : out) {
    const std::string& output = b.shards.begin()->second.output;
    if (output.empty()) continue;
    const auto [first, fresh] = by_output.emplace(output, &b);
    if (!fresh)
      throw io::BadInput(batch_name(*first->second) + " and " + batch_name(b) +
                         " both merge into " + io::quoted(output, 200) + " in " +
                         io::quoted(dir.string(), 200) +
                         "; merge each in a folder of its own (move one batch's manifests and "
                         "files), or run one again with another --out");
  }
  return out;
}

namespace {

// The names of the lock files in `dir`: read once, not looked for once per
// shard (a batch may have a million).
std::set<std::string> lock_files(const fs::path& dir) {
  std::set<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (auto name = e.path().filename().string(); name.ends_with(".lock"))
      names.insert(std::move(name));
  return names;
}

std::string holder_of(const LockStatus& lock) {
  return (lock.holder ? describe(*lock.holder) : std::string("another process")) + "; " + lock.why;
}

}  // namespace

void check_batch(Batch& b, const fs::path& dir) {
  const auto& any = b.shards.begin()->second;
  const auto locks = lock_files(dir);
  for (long i = 0; i < b.count; ++i) {
    const auto it = b.shards.find(i);
    const bool listed = it != b.shards.end();
    std::vector<std::string> found;
    if (listed && it->second.completed) {
      found = file_problems(it->second, dir);
      if (found.empty()) {
        ++b.complete;
        continue;
      }
    }
    LockStatus lock;
    if (const auto name = b.stem.empty() ? "" : lock_name(b.stem, {i, b.count}); locks.count(name))
      lock = probe_lock(dir / name);
    const std::string tag = "shard " + std::to_string(i) + "/" + std::to_string(b.count) + ": ";
    const bool listing = b.problems.size() < max_listed_problems;
    if (!listing) ++b.unlisted;  // counted without building its lines
    if (lock.state == LockState::running) {
      ++b.running;
      if (listing)
        b.problems.push_back(tag + "running (" + holder_of(lock) +
                             "); merge again once it has ended");
      continue;
    }
    b.incomplete.push_back(i);
    ++(listed || lock.state == LockState::dead ? b.dead : b.missing);
    if (!listing) continue;
    if (lock.state == LockState::dead && !lock.holder)
      found.push_back("dead (" + lock.why + ")");  // no holder: not a lock of epviz
    else if (lock.state == LockState::dead)
      found.push_back("dead (its lock was left by " + holder_of(lock) + ")");
    else if (!listed)
      found.push_back("missing (no manifest in " + io::printable(dir.string(), 300) + ")");
    else if (!it->second.completed)
      found.push_back("dead (not completed, and no process holds its lock: killed or failed)");
    const std::string redo = "; run: " + rerun_command(any, i);
    for (const auto& p : found) b.problems.push_back(tag + p + redo);
  }
}

std::vector<std::string> batch_report(const Batch& b) {
  if (b.complete == b.count) return {};
  std::vector<std::string> lines;
  const std::string name = batch_name(b);
  for (const auto& p : b.problems) lines.push_back(name + ": " + p);
  if (b.unlisted) lines.push_back(name + ": and " + std::to_string(b.unlisted) + " more shards");
  std::string counts = name + ": " + std::to_string(b.complete) + " complete, ";
  counts += std::to_string(b.running) + " running, " + std::to_string(b.dead) + " dead, ";
  counts += std::to_string(b.missing) + " missing";
  lines.push_back(std::move(counts));
  return lines;
}

}  // namespace epviz::shard
