// A sweep's shards: contiguous point ranges, rows files named by shard beside
// the rows file asked for, and a manifest listing that file once completed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "shard/checksum.hpp"
#include "shard/rows_shard.hpp"
#include "support/temp_dir.hpp"

namespace epviz::shard {
namespace {

namespace fs = std::filesystem;

RowsBatch batch_of(const fs::path& rows) {
  return {{"/sweeps/atlas.sweep.json", "beef", {"epviz", "sweep", "/sweeps/atlas.sweep.json"}},
          rows,
          7};
}

TEST(RowsShard, EachShardWritesItsOwnRowsFileBesideTheOneAskedFor) {
  const auto s = plan_rows_shard(batch_of("res/rows.jsonl"), {2, 3});
  EXPECT_EQ(s.points, (ItemRange{5, 7}));  // 7 points: 3, 2, 2
  EXPECT_EQ(s.rows, fs::path("res") / "rows.shard-2-of-3.jsonl");
  EXPECT_EQ(s.manifest_path, fs::path("res") / "rows.shard-2-of-3.manifest.json");
  EXPECT_EQ(s.manifest.kind, "sweep");
  EXPECT_EQ(s.manifest.output, "rows.jsonl");  // what the merge writes
  EXPECT_EQ(s.manifest.items, s.points);
  EXPECT_EQ(s.manifest.total, 7);
  EXPECT_EQ(s.manifest.hash, "beef");
  // A rows file given without a directory: the current one.
  EXPECT_EQ(plan_rows_shard(batch_of("rows.jsonl"), {0, 3}).rows,
            fs::path(".") / "rows.shard-0-of-3.jsonl");
}

TEST(RowsShard, TheManifestIsCompletedWithTheRowsFileAndItsChecksum) {
  const epviz::test::TempDir temp;
  const fs::path& dir = temp.path();
  auto s = plan_rows_shard(batch_of(dir / "rows.jsonl"), {0, 2});
  start_rows_shard(s);
  EXPECT_FALSE(read_manifest(s.manifest_path).completed);
  std::ofstream(s.rows) << "{\"index\":0}\n";
  finish_rows_shard(s);
  const auto m = read_manifest(s.manifest_path);
  EXPECT_TRUE(m.completed);
  ASSERT_EQ(m.files.size(), 1u);
  EXPECT_EQ(m.files[0].path, "rows.shard-0-of-2.jsonl");
  EXPECT_EQ(m.files[0].checksum, checksum_of("{\"index\":0}\n"));
}

}  // namespace
}  // namespace epviz::shard
