#pragma once
// The small JSON file each shard writes beside its output: which batch it
// belongs to (a hash of the batch's canonical content), which shard it is,
// which items it covered, the files it wrote with their checksums, and how to
// run it again. It is written twice: at the start with "completed": false and,
// once every output file is closed, again with "completed": true, so that the
// flag is the last thing to reach the disk.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "shard/shard_spec.hpp"

namespace epviz::shard {

struct ManifestFile {
  std::string path;  // relative to the manifest's directory
  std::uintmax_t bytes = 0;
  std::string checksum;  // shard/checksum.hpp
};

struct Manifest {
  std::string kind;    // "sweep", "render" or "section"
  std::string source;  // the sweep or job file as given
  std::string hash;    // of the batch's canonical content: shards of one batch share it
  ShardSpec shard;
  ItemRange items;  // points or frames
  long total = 0;   // items in the whole batch
  // The command that ran this shard, without its shard options: a missing
  // shard j is rerun by adding "--shard j/N".
  std::vector<std::string> command;
  std::string output;  // what a merge writes (file name), empty when nothing is joined
  std::vector<ManifestFile> files;
  bool completed = false;
};

// What every shard of one batch says alike: where the batch comes from and
// how to run one of its shards again.
struct BatchOrigin {
  std::string source;                // the sweep or job file, absolute
  std::string hash;                  // of the batch's canonical content
  std::vector<std::string> command;  // runs it again, without shard options
};

// The manifest of shard `s`, which does `items` of the batch's `total`,
// before its files are added.
Manifest shard_manifest(std::string kind, const BatchOrigin& origin, const ShardSpec& s,
                        const ItemRange& items, long total, std::string output);

nlohmann::ordered_json to_json(const Manifest& m);
// Strict reading (io/json_reader): throws io::BadInput naming the file and key.
Manifest read_manifest(const std::filesystem::path& path);
// Atomic write (temporary + rename).
void write_manifest(const std::filesystem::path& path, const Manifest& m);

// "<stem>.shard-2-of-8.manifest.json": where shard `s` of a batch named `stem` keeps it.
std::string manifest_name(const std::string& stem, const ShardSpec& s);
inline constexpr std::string_view manifest_suffix = ".manifest.json";
// "<stem>.shard-2-of-8.lock": the lock its process holds while it runs (shard_lock.hpp).
std::string lock_name(const std::string& stem, const ShardSpec& s);
// The stem of a manifest's file name ("rows" of "rows.shard-2-of-8.manifest.json"),
// or "" when the name is not that of shard `s`.
std::string manifest_stem(const std::string& file_name, const ShardSpec& s);

// Adds `file` (a path) to m.files, relative to `dir`, with its size and checksum.
void add_file(Manifest& m, const std::filesystem::path& dir, const std::filesystem::path& file);

// The first part of dir/relative (below `dir`) that is a symbolic link, or
// an empty path when none is.
std::filesystem::path link_within(const std::filesystem::path& dir,
                                  const std::filesystem::path& relative);

// What is wrong with the manifest's files as they are on disk now (missing,
// a symbolic link, other size, other checksum), one line each; empty when all
// are intact.
std::vector<std::string> file_problems(const Manifest& m, const std::filesystem::path& dir);

// The command that ran the shard, without its shard options, as one shell
// line (arguments quoted where needed).
std::string shell_command(const Manifest& m);

// The command to run shard `index` again, as one shell line.
std::string rerun_command(const Manifest& m, long index);

}  // namespace epviz::shard
