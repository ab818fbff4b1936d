// `epviz render --shard I/N`: sharded frames are the unsharded frames, byte
// for byte (PNG), and video segments joined by `epviz merge` decode to the
// frames of the unsharded video.
#include <gtest/gtest.h>

#include <fstream>

#include "io/subprocess.hpp"
#include "support/cli.hpp"

namespace epviz::test {
namespace {

namespace fs = std::filesystem;

// 12 frames of a chaotic top with a trail: each frame depends on the whole history.
const char* kJob = R"({
  "simulation": { "case": "generic", "t_end": 6, "method": "dop853", "tol": "auto" },
  "view": "body", "trail": { "length": 3 },
  "width": 96, "height": 64, "fps": 6, "duration": 2,
  "output": { "dir": "out", "format": "png", "name": "f" }
})";

TEST(RenderShard, ShardedPngFramesAreTheUnshardedBytes) {
  TempDir d;
  std::ofstream(d / "job.json") << kJob;
  const std::string job = (d / "job.json").string();
  ASSERT_EQ(
      run_epviz("render " + job + " --out " + (d / "whole").string() + " --quiet", d).exit_code, 0);
  for (int i = 0; i < 4; ++i) {
    auto r = run_epviz("render " + job + " --out " + (d / "shards").string() + " --quiet --shard " +
                           std::to_string(i) + "/4",
                       d);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  int frames = 0;
  for (const auto& e : fs::directory_iterator(d / "whole")) {
    ++frames;
    const auto other = d / "shards" / e.path().filename();
    ASSERT_TRUE(fs::exists(other)) << other;
    EXPECT_EQ(slurp(e.path()), slurp(other)) << e.path().filename() << " differs";
  }
  EXPECT_EQ(frames, 12);
  // Frames drawn differ from one another (the comparison can fail).
  EXPECT_NE(slurp(d / "whole" / "f_0003.png"), slurp(d / "whole" / "f_0009.png"));
  auto m = run_epviz("merge " + (d / "shards").string(), d);
  EXPECT_EQ(m.exit_code, 0) << m.err;
  EXPECT_NE(m.out.find("12 PNG frames complete"), std::string::npos) << m.out;
  auto bad = run_epviz("render " + job + " --shard 0/2 --frames 1:3", d);
  expect_bad_input(bad, "--frames");
}

// The decoded frames of a video, as raw RGB bytes.
std::string decoded(const fs::path& video) {
  auto r = io::run_process({"ffmpeg", "-hide_banner", "-loglevel", "error", "-i", video.string(),
                            "-f", "rawvideo", "-pix_fmt", "rgb24", "-"});
  EXPECT_TRUE(r.status.success()) << r.err;
  return r.out;
}

TEST(RenderShard, JoinedVideoSegmentsDecodeToTheUnshardedFrames) {
  if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) GTEST_SKIP() << "ffmpeg not installed";
  TempDir d;
  std::ofstream(d / "job.json") << kJob;
  const std::string job = (d / "job.json").string();
  ASSERT_EQ(
      run_epviz("render " + job + " --format mp4 --out " + (d / "whole").string() + " --quiet", d)
          .exit_code,
      0);
  for (int i = 0; i < 3; ++i)
    ASSERT_EQ(run_epviz("render " + job + " --format mp4 --out " + (d / "shards").string() +
                            " --quiet --shard " + std::to_string(i) + "/3",
                        d)
                  .exit_code,
              0);
  auto m = run_epviz("merge " + (d / "shards").string(), d);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const std::string whole = decoded(d / "whole" / "f.mp4");
  const std::string joined = decoded(d / "shards" / "f.mp4");
  const std::size_t frame_bytes = 96 * 64 * 3;
  ASSERT_EQ(whole.size(), 12 * frame_bytes);
  ASSERT_EQ(joined.size(), whole.size());
  // Lossy encoding with other key frames: equal up to compression noise.
  // Each joined frame must be nearer to the unsharded frame of its number than
  // to any other frame (a segment out of place or a frame lost fails this),
  // and near in absolute terms (a few levels of 255 on average).
  auto distance = [&](std::size_t a, std::size_t b) {
    double diff = 0.0;
    for (std::size_t k = 0; k < frame_bytes; ++k)
      diff += std::abs(int(static_cast<unsigned char>(joined[a * frame_bytes + k])) -
                       int(static_cast<unsigned char>(whole[b * frame_bytes + k])));
    return diff / double(frame_bytes);
  };
  for (std::size_t f = 0; f < 12; ++f) {
    const double same = distance(f, f);
    EXPECT_LT(same, 6.0) << "frame " << f;
    for (std::size_t g = 0; g < 12; ++g)
      if (g != f) {
        EXPECT_LT(same, distance(f, g)) << "frame " << f << " is nearer to frame " << g;
      }
  }
}

}  // namespace
}  // namespace epviz::test
