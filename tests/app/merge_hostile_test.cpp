// `epviz merge` of manifests other machines or users wrote: one that would
// make it write or read outside its folder, run ffmpeg on rows or echo a
// foreign command is refused before any work, on one line naming the file and
// key; a batch of a million missing shards is summarised, not listed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"
#include "support/temp_dir.hpp"
#include "support/tiny_sweep.hpp"

namespace epviz::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// "shards" holding one lawful, completed shard (0 of 1) of a sweep of two
// points, whose merge would write shards/rows.jsonl.
class MergeHostile : public ::testing::Test {
 protected:
  TempDir d_;
  fs::path shards_ = d_ / "shards";
  fs::path merged_ = shards_ / "rows.jsonl";
  fs::path manifest_;

  void SetUp() override {
    manifest_ = run_tiny_sweep_shard(d_, shards_);  // its rows named merged_
    ASSERT_FALSE(manifest_.empty());
  }
  void edit(const std::function<void(Json&)>& change) {
    Json j = Json::parse(slurp(manifest_));
    change(j);
    std::ofstream(manifest_, std::ios::trunc) << j.dump();
  }
  CliResult merge() { return run_epviz("merge " + shards_.string(), d_); }
};

TEST_F(MergeHostile, TheLawfulShardMerges) {
  EXPECT_EQ(merge().exit_code, 0);
  EXPECT_EQ(line_count(slurp(merged_)), 2u);
}

TEST_F(MergeHostile, AnOutputOutsideTheFolderIsRefusedAndTheVictimKept) {
  const fs::path victim = d_ / "victim";
  for (const std::string& output : {victim.string(), std::string("../victim")}) {
    std::ofstream(victim, std::ios::trunc) << "precious";
    edit([&](Json& j) { j["output"] = output; });
    expect_bad_input(merge(), "key 'output'");
    EXPECT_EQ(slurp(victim), "precious") << output;
  }
}

TEST_F(MergeHostile, AFileOutsideTheFolderIsNotRead) {
  // The same bytes outside: size and checksum agree with the manifest.
  const std::string rows_name = Json::parse(slurp(manifest_))["files"][0]["path"];
  fs::copy_file(shards_ / rows_name, d_ / "x.jsonl");
  for (const std::string& path : {std::string("../x.jsonl"), (d_ / "x.jsonl").string()}) {
    edit([&](Json& j) { j["files"][0]["path"] = path; });
    expect_bad_input(merge(), "key 'files[0].path'");
    EXPECT_FALSE(fs::exists(merged_)) << path;
  }
}

// Symbolic links inside the folder may lead anywhere: the merged file is not
// written through one, and a shard's file that is one is not read.
TEST_F(MergeHostile, ALinkInTheFolderIsNeitherWrittenThroughNorRead) {
  const fs::path victim = d_ / "victim";
  std::ofstream(victim) << "precious";
  fs::create_symlink(victim, merged_);
  expect_bad_input(merge(), "rows.jsonl: is a symbolic link");
  EXPECT_EQ(slurp(victim), "precious");
  fs::remove(merged_);

  // The shard's rows moved out and linked back: same bytes, read through a link.
  const std::string rows_name = Json::parse(slurp(manifest_))["files"][0]["path"];
  fs::rename(shards_ / rows_name, d_ / "outside.jsonl");
  fs::create_symlink(d_ / "outside.jsonl", shards_ / rows_name);
  const auto m = merge();
  EXPECT_EQ(m.exit_code, 4) << m.err;
  EXPECT_NE(m.err.find("a symbolic link, not a shard's file"), std::string::npos) << m.err;
  EXPECT_FALSE(fs::exists(merged_));
}

TEST_F(MergeHostile, ARowsFileIsNotHandedToFfmpegAsARender) {
  edit([](Json& j) {
    j["kind"] = "render";
    j["command"][1] = "render";
  });
  expect_bad_input(merge(), "key 'files[0].path'");
  edit([](Json& j) { j["kind"] = "film"; });
  expect_bad_input(merge(), "key 'kind'");
}

TEST_F(MergeHostile, AForeignCommandIsNotEchoedAsAdvice) {
  edit([](Json& j) {
    j["command"] = {"rm", "-rf", "/"};
    j["completed"] = false;  // so that the merge would advise rerunning it
  });
  const auto r = merge();
  expect_bad_input(r, "key 'command'");
  EXPECT_EQ(r.err.find("run: rm"), std::string::npos) << r.err;
}

// A metric no row has is known once the rows are read: refused then, before
// the merged rows are written; the metric quoted escaped and short.
TEST_F(MergeHostile, AnAtlasOfAnUnknownMetricIsRefusedBeforeAnythingIsWritten) {
  const std::string metric = "bo\ngus\x1b[31m" + std::string(3000, 'x');
  const auto r =
      run_epviz("merge " + shards_.string() + " --atlas '" + metric + ":energy:energy'", d_);
  expect_bad_input(r, "no row has this metric");
  EXPECT_NE(r.err.find("atlas 'bo\\ngus\\u001b[31mxxx"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(merged_)) << "rows written before the atlas was checked";
}

// An empty output would make the merge write the folder itself.
TEST_F(MergeHostile, AnEmptyOutputOfASweepIsRefusedNamingTheFileAndKey) {
  edit([](Json& j) { j["output"] = ""; });
  const auto r = merge();
  expect_bad_input(r, manifest_.filename().string() + ": key 'output'");
}

TEST_F(MergeHostile, AMillionMissingShardsAreSummarisedInAFewLines) {
  edit([](Json& j) {
    j["shards"] = 1000000;
    j["first"] = 0;
    j["end"] = 1;  // shard 0 of a million of 2 points does point 0
  });
  const auto r = merge();
  EXPECT_EQ(r.exit_code, 4) << r.err.substr(0, 500);
  EXPECT_LE(line_count(r.err), 12u) << r.err.substr(0, 500);
  EXPECT_NE(r.err.find("shard 1/1000000: missing"), std::string::npos) << r.err.substr(0, 500);
  EXPECT_NE(r.err.find("and 999991 more shards"), std::string::npos) << r.err.substr(0, 2000);
  EXPECT_FALSE(fs::exists(merged_));
}

}  // namespace
}  // namespace epviz::test
