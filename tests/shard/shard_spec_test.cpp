#include <gtest/gtest.h>

#include <map>

#include "shard/shard_spec.hpp"

namespace epviz::shard {
namespace {

Environment env_of(std::map<std::string, std::string> vars) {
  return [vars](const std::string& name) -> std::optional<std::string> {
    auto it = vars.find(name);
    if (it == vars.end()) return std::nullopt;
    return it->second;
  };
}

TEST(ShardSpec, ParsesIndexOfCount) {
  EXPECT_EQ(parse_shard("0/1"), (ShardSpec{0, 1}));
  EXPECT_EQ(parse_shard("2/8"), (ShardSpec{2, 8}));
  EXPECT_EQ(parse_shard("999/1000"), (ShardSpec{999, 1000}));
}

TEST(ShardSpec, RefusesWhatIsNotAShardNamingTheOption) {
  for (const char* bad :
       {"8/8", "-1/2", "1/-2", "a/b", "1/0", "3", "", "/", "1/2x", " 1/2", "1/2/3", "0/1000001"}) {
    try {
      parse_shard(bad, "--shard");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const ShardError& e) {
      EXPECT_NE(std::string(e.what()).find("--shard: expected I/N"), std::string::npos) << e.what();
    }
  }
}

TEST(ShardSpec, SlurmArrayTasksCountFromTheArrayMinimum) {
  // --array=4-7: tasks 4..7 are shards 0..3.
  EXPECT_EQ(shard_from_environment(env_of({{"SLURM_ARRAY_TASK_ID", "5"},
                                           {"SLURM_ARRAY_TASK_MIN", "4"},
                                           {"SLURM_ARRAY_TASK_COUNT", "4"}}),
                                   0),
            (ShardSpec{1, 4}));
  EXPECT_EQ(shard_from_environment(
                env_of({{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_COUNT", "4"}}), 0),
            (ShardSpec{3, 4}));
  EXPECT_THROW(shard_from_environment(env_of({{"SLURM_ARRAY_TASK_ID", "8"},
                                              {"SLURM_ARRAY_TASK_MIN", "4"},
                                              {"SLURM_ARRAY_TASK_COUNT", "4"}}),
                                      0),
               ShardError);
  EXPECT_THROW(shard_from_environment(env_of({{"SLURM_ARRAY_TASK_ID", "1"}}), 0), ShardError);
  // --array=0-15:4: tasks 0, 4, 8, 12 are not consecutive shards.
  EXPECT_THROW(shard_from_environment(env_of({{"SLURM_ARRAY_TASK_ID", "0"},
                                              {"SLURM_ARRAY_TASK_MIN", "0"},
                                              {"SLURM_ARRAY_TASK_MAX", "12"},
                                              {"SLURM_ARRAY_TASK_COUNT", "4"}}),
                                      0),
               ShardError);
}

TEST(ShardSpec, IndexOnlyEnvironmentsNeedTheCount) {
  EXPECT_THROW(shard_from_environment(env_of({{"JOB_COMPLETION_INDEX", "2"}}), 0), ShardError);
  EXPECT_EQ(shard_from_environment(env_of({{"JOB_COMPLETION_INDEX", "2"}}), 5), (ShardSpec{2, 5}));
  EXPECT_EQ(shard_from_environment(env_of({{"AWS_BATCH_JOB_ARRAY_INDEX", "0"}}), 3),
            (ShardSpec{0, 3}));
  EXPECT_THROW(shard_from_environment(env_of({{"AWS_BATCH_JOB_ARRAY_INDEX", "3"}}), 3), ShardError);
  EXPECT_THROW(shard_from_environment(env_of({{"AWS_BATCH_JOB_ARRAY_INDEX", "x"}}), 3), ShardError);
  EXPECT_EQ(shard_from_environment(env_of({}), 4), std::nullopt);
}

// The message of the ShardError `f` throws, or "" when it throws none.
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const ShardError& e) {
    return e.what();
  }
  return "";
}

// Two schedulers' index variables that name different shards: which one
// started this task is unknown, so neither is picked.
TEST(ShardSpec, IndexVariablesThatDisagreeAreRefusedNamingBoth) {
  const auto refusal = [](std::map<std::string, std::string> vars, long count) {
    try {
      shard_from_environment(env_of(std::move(vars)), count);
    } catch (const ShardError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refusal({{"JOB_COMPLETION_INDEX", "1"}, {"AWS_BATCH_JOB_ARRAY_INDEX", "2"}}, 4),
            "JOB_COMPLETION_INDEX=1 and AWS_BATCH_JOB_ARRAY_INDEX=2 disagree on which shard this "
            "task runs; unset the variable of the scheduler that did not start it, or pass "
            "--shard I/N");
  const auto slurm = refusal({{"SLURM_ARRAY_TASK_ID", "3"},
                              {"SLURM_ARRAY_TASK_MIN", "1"},
                              {"SLURM_ARRAY_TASK_COUNT", "4"},
                              {"JOB_COMPLETION_INDEX", "3"}},
                             0);
  EXPECT_EQ(slurm.rfind("SLURM_ARRAY_TASK_ID=3 (from 1) and JOB_COMPLETION_INDEX=3 disagree", 0),
            0u)
      << slurm;
  // Saying the same shard is no conflict: Slurm's task 3 of an array from 1 is shard 2.
  EXPECT_EQ(shard_from_environment(env_of({{"SLURM_ARRAY_TASK_ID", "3"},
                                           {"SLURM_ARRAY_TASK_MIN", "1"},
                                           {"SLURM_ARRAY_TASK_COUNT", "4"},
                                           {"AWS_BATCH_JOB_ARRAY_INDEX", "2"}}),
                                   0),
            (ShardSpec{2, 4}));
  EXPECT_EQ(shard_from_environment(
                env_of({{"JOB_COMPLETION_INDEX", "1"}, {"AWS_BATCH_JOB_ARRAY_INDEX", "1"}}), 4),
            (ShardSpec{1, 4}));
}

TEST(ShardOptions, TheOptionWinsOverTheEnvironment) {
  const auto slurm = env_of({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}});
  EXPECT_EQ(shard_from_options("2/3", "", slurm), (ShardSpec{2, 3}));
  EXPECT_EQ(shard_from_options("2/3", "3", slurm), (ShardSpec{2, 3}));
  EXPECT_EQ(shard_from_options("", "", slurm), (ShardSpec{1, 4}));
  EXPECT_EQ(shard_from_options("", "", env_of({})), std::nullopt);
  EXPECT_EQ(shard_from_options("", "6", env_of({})), std::nullopt);  // no array job: all of it
}

TEST(ShardOptions, ACountThatContradictsTheSlurmArrayIsRefused) {
  const auto slurm = env_of({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}});
  try {
    shard_from_options("", "8", slurm);
    FAIL() << "--shard-count 8 in an array of 4 tasks was taken";
  } catch (const ShardError& e) {
    EXPECT_NE(std::string(e.what()).find("--shard-count 8"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("SLURM_ARRAY_TASK_COUNT 4"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(shard_from_options("", "4", slurm), (ShardSpec{1, 4}));  // the same count is fine
}

TEST(ShardOptions, TheCountCompletesAnIndexOnlyEnvironment) {
  EXPECT_EQ(shard_from_options("", "5", env_of({{"JOB_COMPLETION_INDEX", "4"}})),
            (ShardSpec{4, 5}));
  EXPECT_NE(refusal([] {
              shard_from_options("", "", env_of({{"JOB_COMPLETION_INDEX", "4"}}));
            }).find("JOB_COMPLETION_INDEX is set but the number of shards is not known"),
            std::string::npos);
}

TEST(ShardOptions, RefusalsNameTheOption) {
  const auto none = env_of({});
  EXPECT_EQ(refusal([&] { shard_from_options("1/4", "3", none); }),
            "--shard-count: 3 disagrees with --shard '1/4'; give one of them");
  for (const char* bad : {"0", "-2", "x", "1000001", "2.5"})
    EXPECT_EQ(
        refusal([&] { shard_from_options("", bad, none); }),
        "--shard-count: expected a whole number from 1 to 1000000, got '" + std::string(bad) + "'");
  EXPECT_NE(refusal([&] { shard_from_options("4/4", "", none); }).find("--shard: expected I/N"),
            std::string::npos);
}

TEST(ShardSpec, RangesAreContiguousCoverEverythingAndDifferByAtMostOne) {
  for (long total = 0; total <= 60; ++total)
    for (long count = 1; count <= 11; ++count) {
      long next = 0, smallest = total, largest = 0;
      for (long i = 0; i < count; ++i) {
        const auto r = shard_range(total, {i, count});
        EXPECT_EQ(r.first, next) << total << " " << i << "/" << count;
        EXPECT_GE(r.end, r.first);
        smallest = std::min(smallest, r.size());
        largest = std::max(largest, r.size());
        next = r.end;
      }
      EXPECT_EQ(next, total);
      EXPECT_LE(largest - smallest, 1) << total << " in " << count;
    }
  // Large sizes do not overflow.
  EXPECT_EQ(shard_range(1L << 50, {3, 4}).end, 1L << 50);
}

}  // namespace
}  // namespace epviz::shard
