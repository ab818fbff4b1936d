// What a merge finds in a directory of shards: batches by hash, what keeps
// each from being merged, and a sweep's rows joined in point order.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/bad_input.hpp"
#include "io/temp_name.hpp"
#include "shard/batch.hpp"
#include "shard/merged_rows.hpp"
#include "shard/shard_lock.hpp"
#include "support/dead_pid.hpp"
#include "support/temp_dir.hpp"

namespace epviz::shard {
namespace {

namespace fs = std::filesystem;

class Merge : public ::testing::Test {
 protected:
  epviz::test::TempDir temp_;
  const fs::path& dir_ = temp_.path();

  // Shard `index` of a 2-shard sweep of 4 points with hash `hash`, its rows
  // file holding `rows` (one JSON object a line).
  void write_shard(const std::string& hash, long index, const std::string& rows, long count = 2) {
    Manifest m;
    m.kind = "sweep";
    m.source = "/s/" + hash + ".sweep.json";
    m.hash = hash;
    m.shard = {index, count};
    m.items = shard_range(4, m.shard);
    m.total = 4;
    m.command = {"epviz", "sweep", m.source};
    m.output = hash + ".jsonl";
    const std::string stem = hash + "-" + std::to_string(count);
    const fs::path file = dir_ / (stem + "." + shard_tag(m.shard) + ".jsonl");
    std::ofstream(file) << rows;
    add_file(m, dir_, file);
    m.completed = true;
    write_manifest(dir_ / manifest_name(stem, m.shard), m);
  }
  // Why the first batch's rows cannot be merged ("" when they can).
  std::string merge_refusal() {
    try {
      merged_rows(read_batches(dir_).at(0), dir_);
    } catch (const io::BadInput& e) {
      return e.what();
    }
    return "";
  }
  // Shard `index`'s manifest (of a 2-shard split) with `key` set to `value`.
  void edit_manifest(long index, const std::string& key, const nlohmann::json& value) {
    const fs::path file = dir_ / manifest_name("aa-2", {index, 2});
    auto j = nlohmann::json::parse(test::slurp(file));
    j[key] = value;
    std::ofstream(file, std::ios::trunc) << j.dump();
  }
  static std::string row(long index, const std::string& hash) {
    return R"({"index":)" + std::to_string(index) + R"(,"sweep":")" + hash + "\"}\n";
  }
};

TEST_F(Merge, ShardsOfOneSweepFormOneBatchAndAMissingShardIsNamedWithItsCommand) {
  write_shard("aa", 0, row(0, "aa") + row(1, "aa"));
  write_shard("aa", 1, row(2, "aa") + row(3, "aa"));
  write_shard("bb", 1, row(2, "bb") + row(3, "bb"));
  auto batches = read_batches(dir_);
  ASSERT_EQ(batches.size(), 2u);
  EXPECT_EQ(batches[0].hash, "aa");
  EXPECT_EQ(batch_name(batches[0]), "sweep /s/aa.sweep.json (2 shards)");
  check_batch(batches[0], dir_);
  EXPECT_TRUE(batches[0].problems.empty());
  check_batch(batches[1], dir_);
  ASSERT_EQ(batches[1].problems.size(), 1u);
  EXPECT_EQ(batches[1].problems[0].rfind("shard 0/2: missing", 0), 0u) << batches[1].problems[0];
  EXPECT_NE(batches[1].problems[0].find("run: epviz sweep /s/bb.sweep.json --shard 0/2"),
            std::string::npos)
      << batches[1].problems[0];

  const auto rows = merged_rows(batches[0], dir_);
  ASSERT_EQ(rows.size(), 4u);
  for (long i = 0; i < 4; ++i) EXPECT_EQ(rows[std::size_t(i)]["index"], i);
}

TEST_F(Merge, ShardsOfAnOldSplitBesideANewOneAreRefused) {
  write_shard("aa", 0, row(0, "aa") + row(1, "aa"));
  write_shard("aa", 0, row(0, "aa"), 4);
  EXPECT_THROW(read_batches(dir_), io::BadInput);
}

TEST_F(Merge, RowsThatAreNotTheShardsPointsAreRefused) {
  write_shard("aa", 0, row(0, "aa") + row(3, "aa"));  // point 3 is shard 1's
  write_shard("aa", 1, row(2, "aa") + row(3, "aa"));
  EXPECT_NE(merge_refusal().find("not one of shard 0's points"), std::string::npos)
      << merge_refusal();
}

TEST_F(Merge, APointWithoutARowIsNamedWithTheCommandThatRedoesItsShard) {
  write_shard("aa", 0, row(0, "aa"));
  write_shard("aa", 1, row(2, "aa") + row(3, "aa"));
  EXPECT_NE(merge_refusal().find("shard 0/2: point 1 has no row; run: epviz sweep"),
            std::string::npos)
      << merge_refusal();
}

TEST_F(Merge, HostileRowsAreRefusedNamingTheFileAndLine) {
  for (const std::string bad :
       {R"({"index":"1","sweep":"aa"})", R"({"index":1,"sweep":7})",
        R"({"index":1.5,"sweep":"aa"})", R"([1,"aa"])", R"({"sweep":"aa"})"}) {
    write_shard("aa", 0, row(0, "aa") + bad + "\n");
    write_shard("aa", 1, row(2, "aa") + row(3, "aa"));
    const auto why = merge_refusal();
    EXPECT_NE(why.find("aa-2.shard-0-of-2.jsonl: line 2: expected an object"), std::string::npos)
        << bad << ": " << why;
  }
}

// Two sweeps whose shards went into one folder under one --out: the later
// batch's rows would replace the earlier's. Refused, naming both sweeps.
TEST_F(Merge, TwoBatchesThatMergeIntoOneNameAreRefusedNamingBoth) {
  for (const std::string hash : {"aa", "bb"}) {
    write_shard(hash, 0, row(0, hash) + row(1, hash));
    write_shard(hash, 1, row(2, hash) + row(3, hash));
  }
  for (long i : {0, 1}) {
    const fs::path file = dir_ / manifest_name("bb-2", {i, 2});
    auto j = nlohmann::json::parse(test::slurp(file));
    j["output"] = "aa.jsonl";
    std::ofstream(file, std::ios::trunc) << j.dump();
  }
  try {
    read_batches(dir_);
    FAIL() << "two batches merged into one file";
  } catch (const io::BadInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("sweep /s/aa.sweep.json (2 shards) and sweep /s/bb.sweep.json (2 shards) "
                        "both merge into 'aa.jsonl'"),
              std::string::npos)
        << what;
  }
}

TEST_F(Merge, ARangeWithAGapBetweenShardsIsRefused) {
  // Shard 1 claims points 3.. only: point 2 would belong to no shard.
  write_shard("aa", 0, row(0, "aa") + row(1, "aa"));
  write_shard("aa", 1, row(3, "aa"));
  edit_manifest(1, "first", 3);
  try {
    read_batches(dir_);
    FAIL() << "a gap at point 2 was accepted";
  } catch (const io::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("key 'first'"), std::string::npos) << e.what();
  }
  // The same gap made by another total: shard 1 of 2 of 6 points does 3..5.
  edit_manifest(1, "total", 6);
  edit_manifest(1, "end", 6);
  try {
    read_batches(dir_);
    FAIL() << "shards of 4 and 6 points were accepted as one batch";
  } catch (const io::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("key 'total'"), std::string::npos) << e.what();
  }
}

TEST_F(Merge, ShardsOfOneBatchThatNameTwoOutputsAreRefused) {
  write_shard("aa", 0, row(0, "aa") + row(1, "aa"));
  write_shard("aa", 1, row(2, "aa") + row(3, "aa"));
  edit_manifest(1, "output", "other.jsonl");
  EXPECT_THROW(read_batches(dir_), io::BadInput);
}

TEST_F(Merge, RunningDeadAndMissingShardsAreToldApartAndOnlyDeadOrMissingOnesRedone) {
  // Of five shards: 0 complete; 1 running (its lock held); 2 killed (its
  // lock left by a pid that is gone); 3 failed (not completed, no lock); 4 missing.
  for (long i = 0; i < 4; ++i) write_shard("aa", i, i == 0 ? row(0, "aa") : "", 5);
  for (long i = 1; i < 4; ++i) {
    const fs::path file = dir_ / manifest_name("aa-5", {i, 5});
    auto j = nlohmann::json::parse(test::slurp(file));
    j["completed"] = false;
    std::ofstream(file, std::ios::trunc) << j.dump();
  }
  const ShardLock running(dir_ / lock_name("aa-5", {1, 5}));
  std::ofstream(dir_ / lock_name("aa-5", {2, 5})) << nlohmann::json{
      {"host", "here"},
      {"machine", io::machine_token()},
      {"pid", test::dead_pid()},
      {"started", "2026-01-02T03:04:05Z"}}.dump();
  auto batches = read_batches(dir_);
  ASSERT_EQ(batches.size(), 1u);
  auto& b = batches[0];
  check_batch(b, dir_);
  EXPECT_EQ(b.incomplete, (std::vector<long>{2, 3, 4}));
  ASSERT_EQ(b.problems.size(), 4u);
  const std::string pid = std::to_string(::getpid());
  EXPECT_EQ(b.problems[0].rfind("shard 1/5: running (host ", 0), 0u) << b.problems[0];
  EXPECT_NE(b.problems[0].find(", pid " + pid + ", since "), std::string::npos) << b.problems[0];
  EXPECT_EQ(b.problems[0].find("run:"), std::string::npos) << b.problems[0];
  EXPECT_EQ(b.problems[1].rfind("shard 2/5: dead (its lock was left by host here, pid ", 0), 0u)
      << b.problems[1];
  EXPECT_NE(b.problems[1].find("no such process on this host); run: epviz sweep"),
            std::string::npos)
      << b.problems[1];
  EXPECT_EQ(b.problems[2].rfind("shard 3/5: dead (not completed, and no process holds", 0), 0u)
      << b.problems[2];
  EXPECT_EQ(b.problems[3].rfind("shard 4/5: missing", 0), 0u) << b.problems[3];
  for (std::size_t i = 1; i < 4; ++i)
    EXPECT_NE(b.problems[i].find("--shard " + std::to_string(i + 1) + "/5"), std::string::npos)
        << b.problems[i];
  EXPECT_EQ(batch_report(b).back(), batch_name(b) + ": 1 complete, 1 running, 2 dead, 1 missing");
}

TEST_F(Merge, ACompleteBatchHasNothingToReport) {
  write_shard("aa", 0, row(0, "aa") + row(1, "aa"));
  write_shard("aa", 1, row(2, "aa") + row(3, "aa"));
  auto batches = read_batches(dir_);
  check_batch(batches.at(0), dir_);
  EXPECT_TRUE(batch_report(batches[0]).empty());
  EXPECT_EQ(batches[0].complete, 2);
}

TEST_F(Merge, APointTwiceIsMergedOnceWhenItsRowsAreTheSameAndRefusedWhenTheyDiffer) {
  // Two runs of point 0: the same but for the CPU time each measured.
  write_shard("aa", 0,
              R"({"index":0,"sweep":"aa","cpu_seconds":0.25})"
              "\n" +
                  row(1, "aa") + R"({"index":0,"sweep":"aa","cpu_seconds":0.5})" + "\n");
  write_shard("aa", 1, row(2, "aa") + row(3, "aa") + row(3, "aa"));
  const auto rows = merged_rows(read_batches(dir_).at(0), dir_);
  ASSERT_EQ(rows.size(), 4u);
  for (long i = 0; i < 4; ++i) EXPECT_EQ(rows[std::size_t(i)]["index"], i);
  EXPECT_EQ(rows[0]["cpu_seconds"], 0.25);  // the first kept

  write_shard("aa", 1, row(2, "aa") + row(3, "aa") + R"({"index":2,"sweep":"aa","x":1})" + "\n");
  const auto why = merge_refusal();
  EXPECT_NE(why.find("aa-2.shard-1-of-2.jsonl: line 1 and "), std::string::npos) << why;
  EXPECT_NE(why.find("aa-2.shard-1-of-2.jsonl: line 3: two different rows of point 2"),
            std::string::npos)
      << why;
}

TEST_F(Merge, AMillionMissingShardsListOnlyAFew) {
  write_shard("aa", 0, row(0, "aa"), max_shards);
  auto batches = read_batches(dir_);
  ASSERT_EQ(batches.size(), 1u);
  check_batch(batches[0], dir_);
  EXPECT_EQ(batches[0].problems.size(), max_listed_problems);
  EXPECT_EQ(batches[0].unlisted, max_shards - 1 - long(max_listed_problems));
  EXPECT_EQ(batches[0].problems.back().rfind("shard 8/1000000: missing", 0), 0u)
      << batches[0].problems.back();
}

}  // namespace
}  // namespace epviz::shard
