#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/json_reader.hpp"
#include "shard/checksum.hpp"
#include "shard/manifest.hpp"
#include "support/temp_dir.hpp"

namespace epviz::shard {
namespace {

namespace fs = std::filesystem;

TEST(Checksum, IsFnv1a64OfTheBytes) {
  // The published FNV-1a 64 test vectors.
  EXPECT_EQ(checksum_of(""), "cbf29ce484222325");
  EXPECT_EQ(checksum_of("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(checksum_of("foobar"), "85944171f73967e8");
}

TEST(Manifest, RoundTripsAndFindsChangedFiles) {
  test::TempDir d;
  std::ofstream(d / "rows.jsonl") << "{\"index\":0}\n";
  Manifest m;
  m.kind = "sweep";
  m.source = "/x/a b.sweep.json";
  m.hash = "0123";
  m.shard = {1, 3};
  m.items = {4, 8};
  m.total = 12;
  m.command = {"epviz", "sweep", "/x/a b.sweep.json", "--out", "/x/rows.jsonl"};
  m.output = "rows.jsonl";
  add_file(m, d.path(), d / "rows.jsonl");
  m.completed = true;
  const auto path = d / manifest_name("rows", m.shard);
  EXPECT_EQ(path.filename(), "rows.shard-1-of-3.manifest.json");
  write_manifest(path, m);
  const auto back = read_manifest(path);
  EXPECT_EQ(to_json(back), to_json(m));
  EXPECT_TRUE(file_problems(back, d.path()).empty());

  std::ofstream(d / "rows.jsonl") << "{\"index\":1}\n";  // same size, other bytes
  const auto p = file_problems(back, d.path());
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("checksum"), std::string::npos) << p[0];
  fs::remove(d / "rows.jsonl");
  EXPECT_NE(file_problems(back, d.path()).at(0).find("missing"), std::string::npos);

  EXPECT_EQ(rerun_command(m, 2), "epviz sweep '/x/a b.sweep.json' --out /x/rows.jsonl --shard 2/3");
}

TEST(Manifest, ReadingIsStrict) {
  test::TempDir d;
  std::ofstream(d / "m.json") << R"({"kind":"sweep","source":"s","hash":"ab","shard":3,)"
                                 R"("shards":2,"first":0,"end":1,"total":1,"command":[],)"
                                 R"("output":"","files":[],"completed":true})";
  try {
    read_manifest(d / "m.json");
    FAIL() << "accepted shard 3 of 2";
  } catch (const io::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("'shard'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace epviz::shard
