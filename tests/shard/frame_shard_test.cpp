// A render's shards: contiguous frame ranges, a segment name for a video, and
// a manifest that lists exactly the files the shard drew.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "shard/checksum.hpp"
#include "shard/frame_shard.hpp"
#include "support/temp_dir.hpp"

namespace epviz::shard {
namespace {

namespace fs = std::filesystem;

FrameBatch batch_of(const fs::path& dir, std::string video_extension) {
  FrameBatch b;
  b.origin = {"/jobs/top.json", "feed", {"epviz", "render", "/jobs/top.json"}};
  b.dir = dir;
  b.name = "f";
  b.video_extension = std::move(video_extension);
  b.frames = 10;
  return b;
}

TEST(FrameShard, PngShardsSplitTheFramesAndKeepTheirName) {
  const auto b = batch_of("out", "");
  long next = 0;
  for (long i = 0; i < 3; ++i) {
    const auto s = plan_frame_shard(b, {i, 3});
    EXPECT_EQ(s.frames.first, next);  // contiguous, in shard order
    EXPECT_GE(s.frames.size(), 3);
    next = s.frames.end;
    EXPECT_EQ(s.output_name, "f");
    EXPECT_EQ(s.manifest.kind, "render");
    EXPECT_EQ(s.manifest.items, s.frames);
    EXPECT_EQ(s.manifest.total, 10);
    EXPECT_EQ(s.manifest.command, b.origin.command);
    EXPECT_EQ(s.manifest.output, "");  // frames are not joined
    EXPECT_EQ(s.manifest_path,
              fs::path("out") / ("f_png.shard-" + std::to_string(i) + "-of-3.manifest.json"));
  }
  EXPECT_EQ(next, 10);
}

TEST(FrameShard, AVideoShardWritesASegmentTheMergeJoinsIntoTheWhole) {
  const auto s = plan_frame_shard(batch_of("out", ".webm"), {1, 2});
  EXPECT_EQ(s.output_name, "f.shard-1-of-2");
  EXPECT_EQ(s.manifest.output, "f.webm");
  EXPECT_EQ(s.manifest_path, fs::path("out") / "f.shard-1-of-2.manifest.json");
}

TEST(FrameShard, MoreShardsThanFramesIsRefusedNamingTheLimit) {
  try {
    plan_frame_shard(batch_of("out", ""), {10, 11});
    FAIL() << "a shard without frames was planned";
  } catch (const ShardError& e) {
    EXPECT_NE(std::string(e.what()).find("--shard: 11 shards of a job of 10 frames"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("use at most 10 shards"), std::string::npos) << e.what();
  }
}

TEST(FrameShard, TheFinishedManifestListsTheShardsFramesWithTheirChecksums) {
  epviz::test::TempDir d;
  const auto b = batch_of(d.path(), "");
  auto s = plan_frame_shard(b, {1, 2});  // frames 5..9
  start_frame_shard(s);
  EXPECT_FALSE(read_manifest(s.manifest_path).completed);
  for (int i = 0; i < 10; ++i)
    std::ofstream(d.path() / ("f_000" + std::to_string(i) + ".png")) << "frame " << i;
  finish_frame_shard(s, b);
  const auto m = read_manifest(s.manifest_path);
  EXPECT_TRUE(m.completed);
  ASSERT_EQ(m.files.size(), 5u);
  EXPECT_EQ(m.files.front().path, "f_0005.png");
  EXPECT_EQ(m.files.back().path, "f_0009.png");
  EXPECT_EQ(m.files.front().checksum, checksum_of("frame 5"));
  EXPECT_TRUE(file_problems(m, d.path()).empty());
}

TEST(FrameShard, AStartedShardIsHeldUntilItEnds) {
  epviz::test::TempDir d;
  const auto b = batch_of(d.path(), ".mp4");
  {
    auto first = plan_frame_shard(b, {1, 2});
    start_frame_shard(first);
    EXPECT_EQ(first.lock_path, d.path() / "f.shard-1-of-2.lock");
    auto second = plan_frame_shard(b, {1, 2});
    EXPECT_THROW(start_frame_shard(second), ShardBusy);
    auto other = plan_frame_shard(b, {0, 2});
    EXPECT_NO_THROW(start_frame_shard(other));  // another shard: its own lock
  }
  auto again = plan_frame_shard(b, {1, 2});
  EXPECT_NO_THROW(start_frame_shard(again));
}

}  // namespace
}  // namespace epviz::shard
