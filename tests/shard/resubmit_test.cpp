// The Slurm resubmission of a merge's incomplete shards: the --array list
// names exactly those shards, and each task passes its shard explicitly.
#include "shard/resubmit.hpp"

#include <gtest/gtest.h>

namespace epviz::shard {
namespace {

TEST(Resubmit, IndicesBecomeSlurmRanges) {
  EXPECT_EQ(index_ranges({}), "");
  EXPECT_EQ(index_ranges({4}), "4");
  EXPECT_EQ(index_ranges({0, 1, 2, 5, 7, 8}), "0-2,5,7-8");
  EXPECT_EQ(index_ranges({3, 4}), "3-4");
}

TEST(Resubmit, TheScriptRedoesTheIncompleteShardsOfEachBatchThenTheMerge) {
  Batch done, broken;
  Manifest m;
  m.kind = "sweep";
  m.source = "/abs/it's.sweep.json";  // a quote, to be quoted for the shell
  m.shard = {0, 8};
  m.command = {"epviz", "sweep", m.source, "--out", "/abs/out/rows.jsonl"};
  broken.kind = done.kind = "sweep";
  broken.count = done.count = 8;
  broken.shards[0] = done.shards[0] = m;
  broken.incomplete = {2, 5, 6};
  const std::string s = slurm_resubmit_script({done, broken}, {"epviz", "merge", "/abs/out"});
  EXPECT_NE(s.find("--array=2,5-6 "), std::string::npos) << s;
  EXPECT_EQ(s.find("--array=", s.find("--array=") + 1), std::string::npos)
      << "a complete batch got an array:\n"
      << s;
  EXPECT_NE(s.find("--shard \"$SLURM_ARRAY_TASK_ID/8\""), std::string::npos) << s;
  // Quoted twice: for the task's command line, then as --wrap's one word.
  EXPECT_NE(s.find(R"(it'\''\'\'''\''s.sweep.json)"), std::string::npos) << s;
  EXPECT_NE(s.find("--dependency=afterany:\"$deps\""), std::string::npos) << s;
  // The binary as the jobs find it: EPVIZ (which travels with sbatch's environment), else PATH.
  EXPECT_NE(s.find(R"(--wrap 'exec "${EPVIZ:-epviz}" sweep '\'')"), std::string::npos) << s;
  EXPECT_NE(s.find(R"('exec "${EPVIZ:-epviz}" merge /abs/out')"), std::string::npos) << s;
}

}  // namespace
}  // namespace epviz::shard
