#include "shard/rows_shard.hpp"

namespace epviz::shard {

namespace fs = std::filesystem;

namespace {

// "rows.jsonl" -> "rows".
std::string rows_stem(const fs::path& rows, const std::string& extension) {
  std::string s = rows.filename().string();
  return s.ends_with(extension) && s.size() > extension.size()
             ? s.substr(0, s.size() - extension.size())
             : s;
}

}  // namespace

RowsShard plan_rows_shard(const RowsBatch& batch, const ShardSpec& spec) {
  RowsShard s;
  s.shard = spec;
  s.points = shard_range(batch.points, spec);
  const fs::path dir = batch.rows.parent_path().empty() ? fs::path(".") : batch.rows.parent_path();
  const std::string stem = rows_stem(batch.rows, batch.extension);
  s.rows = dir / (stem + "." + shard_tag(spec) + batch.extension);
  s.manifest = shard_manifest(batch.kind, batch.origin, spec, s.points, batch.points,
                              batch.rows.filename().string());
  s.manifest_path = dir / manifest_name(stem, spec);
  s.lock_path = dir / lock_name(stem, spec);
  return s;
}

void start_rows_shard(const RowsShard& s) { write_manifest(s.manifest_path, s.manifest); }

void finish_rows_shard(RowsShard& s) {
  add_file(s.manifest, s.manifest_path.parent_path(), s.rows);
  s.manifest.completed = true;
  write_manifest(s.manifest_path, s.manifest);
}

}  // namespace epviz::shard
