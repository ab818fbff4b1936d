#include "shard/manifest.hpp"

#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "io/json_reader.hpp"
#include "io/json_text.hpp"
#include "io/shell_quote.hpp"
#include "shard/checksum.hpp"
#include "shard/manifest_checks.hpp"

namespace epviz::shard {

namespace fs = std::filesystem;

Manifest shard_manifest(std::string kind, const BatchOrigin& origin, const ShardSpec& s,
                        const ItemRange& items, long total, std::string output) {
  Manifest m;
  m.kind = std::move(kind);
  m.source = origin.source;
  m.hash = origin.hash;
  m.shard = s;
  m.items = items;
  m.total = total;
  m.command = origin.command;
  m.output = std::move(output);
  return m;
}

nlohmann::ordered_json to_json(const Manifest& m) {
  nlohmann::ordered_json j;
  j["kind"] = m.kind;
  j["source"] = m.source;
  j["hash"] = m.hash;
  j["shard"] = m.shard.index;
  j["shards"] = m.shard.count;
  j["first"] = m.items.first;
  j["end"] = m.items.end;
  j["total"] = m.total;
  j["command"] = m.command;
  j["output"] = m.output;
  auto files = nlohmann::ordered_json::array();
  for (const auto& f : m.files)
    files.push_back({{"path", f.path}, {"bytes", f.bytes}, {"checksum", f.checksum}});
  j["files"] = files;
  j["completed"] = m.completed;
  return j;
}

Manifest read_manifest(const fs::path& path) {
  const auto json = io::read_json_file(path);
  const std::string name = path.string();  // ObjectReader quotes it in messages
  io::ObjectReader r(json, name);
  Manifest m;
  // Fails on what `problem` says is wrong with the value at `key`.
  auto check = [](const io::ObjectReader& reader, const char* key, const std::string& problem) {
    if (!problem.empty()) reader.fail(key, problem);
  };
  auto text = [&](const char* key) {
    auto v = r.string(key);
    if (!v) r.fail(key, "missing");
    return *v;
  };
  auto integer = [&](const char* key, long lo, long hi) {
    auto v = r.integer(key, lo, hi);
    if (!v) r.fail(key, "missing");
    return *v;
  };
  const auto kind = r.choice("kind", {"sweep", "render", "section"});
  if (!kind) r.fail("kind", "missing");
  m.kind = *kind;
  m.source = text("source");
  check(r, "source", text_problem(m.source));
  m.hash = text("hash");
  check(r, "hash", hash_problem(m.hash));
  m.shard.count = integer("shards", 1, max_shards);
  m.shard.index = integer("shard", 0, m.shard.count - 1);
  m.total = integer("total", 0, 1L << 50);
  m.items.first = integer("first", 0, m.total);
  m.items.end = integer("end", m.items.first, m.total);
  // Any other range would leave points or frames to no shard, or to two.
  if (m.items != shard_range(m.total, m.shard)) {
    const auto want = shard_range(m.total, m.shard);
    r.fail("first", "shard " + std::to_string(m.shard.index) + " of " +
                        std::to_string(m.shard.count) + " of " + std::to_string(m.total) +
                        " items does " + std::to_string(want.first) + " to " +
                        std::to_string(want.end) + " (first, end), not " +
                        std::to_string(m.items.first) + " to " + std::to_string(m.items.end));
  }
  m.output = text("output");
  check(r, "output", output_name_problem(m.output));
  // Only a render's PNG frames join into nothing; rows and crossings always
  // merge into a file ("" would name the folder itself).
  if (m.output.empty() && m.kind != "render")
    r.fail("output", "a " + m.kind + " shard's merged file: expected a plain file name, got ''");
  const auto* command = r.raw("command");
  if (!command || !command->is_array()) r.fail("command", "expected an array of strings");
  for (const auto& a : *command) {
    if (!a.is_string()) r.fail("command", "expected an array of strings");
    m.command.push_back(a.get<std::string>());
  }
  check(r, "command", command_problem(m.command, m.kind, m.source));
  const auto* files = r.raw("files");
  if (!files || !files->is_array()) r.fail("files", "expected an array of objects");
  for (std::size_t i = 0; i < files->size(); ++i) {
    io::ObjectReader f((*files)[i], name, "files[" + std::to_string(i) + "]");
    ManifestFile mf;
    auto p = f.string("path");
    auto b = f.integer("bytes", 0, 1L << 50);
    auto c = f.string("checksum");
    if (!p || !b || !c) f.fail("path", "each file needs path, bytes and checksum");
    mf.path = *p;
    check(f, "path", file_path_problem(mf.path));
    if (m.kind == "render") check(f, "path", render_file_problem(mf.path, m.output));
    mf.bytes = std::uintmax_t(*b);
    mf.checksum = *c;
    check(f, "checksum", hash_problem(mf.checksum));
    f.finish();
    m.files.push_back(mf);
  }
  const auto done = r.boolean("completed");
  m.completed = done && *done;
  r.finish();
  return m;
}

void write_manifest(const fs::path& path, const Manifest& m) {
  io::write_file_atomically(path, io::json_text(to_json(m), 2) + "\n");
}

std::string manifest_name(const std::string& stem, const ShardSpec& s) {
  return stem + "." + shard_tag(s) + std::string(manifest_suffix);
}

std::string lock_name(const std::string& stem, const ShardSpec& s) {
  return stem + "." + shard_tag(s) + ".lock";
}

std::string manifest_stem(const std::string& file_name, const ShardSpec& s) {
  const std::string tail = manifest_name("", s);
  if (file_name.size() <= tail.size() || !file_name.ends_with(tail)) return "";
  return file_name.substr(0, file_name.size() - tail.size());
}

void add_file(Manifest& m, const fs::path& dir, const fs::path& file) {
  const auto d = digest_file(file);
  m.files.push_back({file.lexically_relative(dir).generic_string(), d.bytes, d.checksum});
}

fs::path link_within(const fs::path& dir, const fs::path& relative) {
  fs::path p = dir;
  for (const auto& part : relative) {
    p /= part;
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(p, ec))) return p;
  }
  return {};
}

std::vector<std::string> file_problems(const Manifest& m, const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& f : m.files) {
    const fs::path p = dir / f.path;
    std::error_code ec;
    if (const auto link = link_within(dir, f.path); !link.empty()) {
      // A shard writes regular files; a link may lead out of the folder.
      out.push_back(link.string() + ": a symbolic link, not a shard's file");
      continue;
    }
    if (!fs::is_regular_file(p, ec)) {
      out.push_back(p.string() + ": missing");
      continue;
    }
    try {
      const auto d = digest_file(p);
      if (d.bytes != f.bytes)
        out.push_back(p.string() + ": " + std::to_string(d.bytes) + " bytes, the manifest says " +
                      std::to_string(f.bytes));
      else if (d.checksum != f.checksum)
        out.push_back(p.string() + ": checksum " + d.checksum + ", the manifest says " +
                      f.checksum);
    } catch (const std::exception& e) {
      out.push_back(e.what());
    }
  }
  return out;
}

std::string shell_command(const Manifest& m) {
  std::string line;
  for (const auto& a : m.command) {
    if (!line.empty()) line.push_back(' ');
    line.append(io::shell_quote(a));
  }
  return line;
}

std::string rerun_command(const Manifest& m, long index) {
  return shell_command(m) + " --shard " + std::to_string(index) + "/" +
         std::to_string(m.shard.count);
}

}  // namespace epviz::shard
