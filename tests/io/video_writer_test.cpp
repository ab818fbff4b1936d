#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/queued_video_writer.hpp"
#include "io/video_writer.hpp"
#include "support/errors.hpp"
#include "support/temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using namespace epviz::io;

class VideoTest : public epviz::test::TempDirTest {
 protected:
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
      names.push_back(entry.path().filename().string());
    return names;
  }
};

// A gradient that moves one column per frame (plus a moving square), top-down rows.
std::vector<std::uint8_t> gradient_frame(int width, int height, int frame) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
      const bool square = x >= frame * 3 && x < frame * 3 + 10 && y >= 10 && y < 20;
      rgba[i + 0] = static_cast<std::uint8_t>((x + frame * 5) * 255 / (width + 60));
      rgba[i + 1] = static_cast<std::uint8_t>(y * 255 / height);
      rgba[i + 2] = square ? 255 : 64;
      rgba[i + 3] = 255;
    }
  return rgba;
}

std::string run_capture(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return out;
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) out.append(buffer.data(), n);
  ::pclose(pipe);
  return out;
}

struct Probe {
  int frames = -1;
  int width = -1;
  int height = -1;
};

Probe ffprobe(const fs::path& file) {
  const std::string json = run_capture(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=nb_read_frames,width,height "
      "-of json '" +
      file.string() + "'");
  Probe probe;
  const auto parsed = nlohmann::json::parse(json, nullptr, false);
  if (parsed.is_discarded() || !parsed.contains("streams") || parsed["streams"].empty()) {
    ADD_FAILURE() << "ffprobe output for " << file << ": " << json;
    return probe;
  }
  const auto& stream = parsed["streams"][0];
  probe.width = stream.value("width", -1);
  probe.height = stream.value("height", -1);
  probe.frames = std::stoi(stream.value("nb_read_frames", std::string("-1")));
  return probe;
}

TEST(VideoFormatTest, NamesAndParsing) {
  EXPECT_EQ(parse_video_format("mp4"), VideoFormat::mp4);
  EXPECT_EQ(parse_video_format("webm"), VideoFormat::webm);
  EXPECT_EQ(parse_video_format("gif"), VideoFormat::gif);
  EXPECT_EQ(parse_video_format("png"), std::nullopt);
  EXPECT_EQ(parse_video_format("MP4"), std::nullopt);
  EXPECT_EQ(video_format_name(VideoFormat::webm), "webm");
  EXPECT_EQ(video_format_extension(VideoFormat::gif), ".gif");
  EXPECT_TRUE(video_format_needs_even_size(VideoFormat::mp4));
  EXPECT_FALSE(video_format_needs_even_size(VideoFormat::gif));
}

TEST(VideoFormatTest, ArgumentsPipeRawRgbaAndQuietLogging) {
  const auto args = ffmpeg_arguments(VideoFormat::mp4, 64, 48, 30, "/x/y z.mp4");
  const std::string joined = [&] {
    std::string s;
    for (const auto& a : args) s += a + " ";
    return s;
  }();
  EXPECT_EQ(args.front(), "ffmpeg");
  EXPECT_EQ(args.back(), "/x/y z.mp4");  // one argument, no shell quoting involved
  EXPECT_NE(joined.find("-f rawvideo -pix_fmt rgba -s 64x48 -r 30 -i - "), std::string::npos)
      << joined;
  EXPECT_NE(joined.find("-nostdin"), std::string::npos);
  EXPECT_NE(joined.find("-loglevel error"), std::string::npos);
  EXPECT_NE(joined.find("-c:v libx264"), std::string::npos);
  EXPECT_NE(joined.find("-pix_fmt yuv420p"), std::string::npos);
  EXPECT_NE(joined.find("+faststart"), std::string::npos);
  const auto webm = ffmpeg_arguments(VideoFormat::webm, 64, 48, 29.97, "a.webm");
  EXPECT_NE(std::find(webm.begin(), webm.end(), "29.97"), webm.end());
  EXPECT_NE(std::find(webm.begin(), webm.end(), "libvpx-vp9"), webm.end());
}

TEST(VideoFormatTest, FfmpegIsInstalled) {
  // ffmpeg is a build requirement (scripts/setup.sh installs it): its absence fails here, never skips.
  ASSERT_TRUE(ffmpeg_available()) << "ffmpeg not found on PATH: install the Debian package ffmpeg";
  ASSERT_TRUE(ffmpeg_available("ffprobe"))
      << "ffprobe not found on PATH: install the Debian package ffmpeg";
  EXPECT_FALSE(ffmpeg_available("epviz-no-such-program"));
  EXPECT_FALSE(ffmpeg_available("/nonexistent/ffmpeg"));
}

class VideoFormats : public VideoTest, public ::testing::WithParamInterface<VideoFormat> {};

TEST_P(VideoFormats, TwelveFramesArePlayableWithTheRightSize) {
  const VideoFormat format = GetParam();
  const fs::path target = dir_ / ("clip with space" + std::string(video_format_extension(format)));
  {
    VideoWriter writer(target, format, 64, 48, 24);
    for (int f = 0; f < 12; ++f) {
      const auto frame = gradient_frame(64, 48, f);
      writer.write_frame(std::span<const std::uint8_t>(frame));
    }
    EXPECT_FALSE(fs::exists(target)) << "the real name appears only on finish()";
    EXPECT_EQ(writer.frames_written(), 12u);
    writer.finish();
    writer.finish();  // idempotent
  }
  ASSERT_TRUE(fs::exists(target));
  EXPECT_GT(fs::file_size(target), 0u);
  EXPECT_EQ(entries(), std::vector<std::string>{target.filename().string()}) << "no temporary left";
  const Probe probe = ffprobe(target);
  EXPECT_EQ(probe.frames, 12);
  EXPECT_EQ(probe.width, 64);
  EXPECT_EQ(probe.height, 48);
}

TEST_P(VideoFormats, DestroyedWithoutFinishLeavesNothing) {
  const VideoFormat format = GetParam();
  const fs::path target = dir_ / ("clip" + std::string(video_format_extension(format)));
  {
    VideoWriter writer(target, format, 64, 48, 24);
    for (int f = 0; f < 5; ++f) writer.write_frame(gradient_frame(64, 48, f).data());
  }
  EXPECT_TRUE(entries().empty());
}

INSTANTIATE_TEST_SUITE_P(AllFormats, VideoFormats,
                         ::testing::Values(VideoFormat::mp4, VideoFormat::webm, VideoFormat::gif),
                         [](const auto& param_info) {
                           return std::string(video_format_name(param_info.param));
                         });

using epviz::test::error_of;

TEST_F(VideoTest, MissingDirectoryFailsClearlyAndLeavesNothing) {
  const fs::path target = dir_ / "missing" / "clip.mp4";
  const std::string message =
      error_of([&] { VideoWriter writer(target, VideoFormat::mp4, 64, 48, 24); });
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  EXPECT_NE(message.find("missing"), std::string::npos) << message;
  EXPECT_TRUE(entries().empty());
}

TEST_F(VideoTest, DirectoryThatIsAFileFailsClearly) {
  std::FILE* f = std::fopen((dir_ / "plain").c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fclose(f);
  const std::string message = error_of(
      [&] { VideoWriter writer(dir_ / "plain" / "clip.gif", VideoFormat::gif, 64, 48, 24); });
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  EXPECT_EQ(entries(), std::vector<std::string>{"plain"});
}

TEST_F(VideoTest, UnwritableDirectoryFailsClearly) {
  if (::geteuid() == 0) GTEST_SKIP() << "root can write anywhere";
  const fs::path locked = dir_ / "locked";
  fs::create_directory(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string message =
      error_of([&] { VideoWriter writer(locked / "clip.mp4", VideoFormat::mp4, 64, 48, 24); });
  fs::permissions(locked, fs::perms::owner_all);
  EXPECT_NE(message.find("not writable"), std::string::npos) << message;
  EXPECT_TRUE(fs::is_empty(locked));
}

TEST_F(VideoTest, OddSizeIsRejectedForYuv420pButNotForGif) {
  const std::string message =
      error_of([&] { VideoWriter writer(dir_ / "odd.mp4", VideoFormat::mp4, 63, 48, 24); });
  EXPECT_NE(message.find("even"), std::string::npos) << message;
  EXPECT_NE(message.find("63x48"), std::string::npos) << message;
  EXPECT_NE(error_of([&] {
              VideoWriter writer(dir_ / "odd.webm", VideoFormat::webm, 64, 47, 24);
            }).find("even"),
            std::string::npos);
  EXPECT_TRUE(entries().empty());

  VideoWriter gif(dir_ / "odd.gif", VideoFormat::gif, 63, 47, 24);
  for (int f = 0; f < 3; ++f) gif.write_frame(gradient_frame(63, 47, f).data());
  gif.finish();
  const Probe probe = ffprobe(dir_ / "odd.gif");
  EXPECT_EQ(probe.width, 63);
  EXPECT_EQ(probe.height, 47);
  EXPECT_EQ(probe.frames, 3);
}

TEST_F(VideoTest, BadArgumentsAreRejected) {
  EXPECT_THROW(VideoWriter(dir_ / "a.mp4", VideoFormat::mp4, 0, 48, 24), std::invalid_argument);
  EXPECT_THROW(VideoWriter(dir_ / "a.mp4", VideoFormat::mp4, 64, 48, 0), std::invalid_argument);
  VideoWriter writer(dir_ / "a.mp4", VideoFormat::mp4, 64, 48, 24);
  std::vector<std::uint8_t> small(10);
  EXPECT_THROW(writer.write_frame(std::span<const std::uint8_t>(small)), std::invalid_argument);
}

TEST_F(VideoTest, MissingFfmpegFailsWithInstallHint) {
  VideoOptions options;
  options.ffmpeg = "epviz-no-such-ffmpeg";
  const std::string message =
      error_of([&] { VideoWriter writer(dir_ / "a.mp4", VideoFormat::mp4, 64, 48, 24, options); });
  EXPECT_NE(
      message.find(
          "ffmpeg not found on PATH: install the Debian package ffmpeg (scripts/setup.sh does)"),
      std::string::npos)
      << message;
  EXPECT_TRUE(entries().empty());
}

TEST_F(VideoTest, NoFramesIsAnErrorAndLeavesNothing) {
  VideoWriter writer(dir_ / "a.mp4", VideoFormat::mp4, 64, 48, 24);
  const std::string message = error_of([&] { writer.finish(); });
  EXPECT_NE(message.find("no frames"), std::string::npos) << message;
  EXPECT_TRUE(entries().empty());
}

TEST_F(VideoTest, FfmpegErrorIsReportedWithItsStderrAndLeavesNothing) {
  // An impossible encoder setting: ffmpeg exits with an error once it sees the first frame.
  VideoOptions options;
  options.x264_preset = "no-such-preset";
  const fs::path target = dir_ / "a.mp4";
  const std::string message = error_of([&] {
    VideoWriter writer(target, VideoFormat::mp4, 64, 48, 24, options);
    // Without SIGPIPE protection one of these writes would kill the test process.
    for (int f = 0; f < 200; ++f) writer.write_frame(gradient_frame(64, 48, f % 12).data());
    writer.finish();
  });
  EXPECT_NE(message.find("cannot write video"), std::string::npos) << message;
  EXPECT_NE(message.find("ffmpeg"), std::string::npos) << message;
  EXPECT_NE(message.find("preset"), std::string::npos) << "ffmpeg's stderr is quoted: " << message;
  EXPECT_TRUE(entries().empty());
}

// The queued writer (io/queued_video_writer.hpp): its thread writes the very
// frames it was given, in order, so the video is the plain writer's byte for
// byte (x264 is deterministic). One buffer is overwritten with each next
// frame as soon as write_frame returns, as the painter does.
std::vector<char> file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(VideoTest, QueuedWriterMakesThePlainWritersVideo) {
  const fs::path plain = dir_ / "plain.mp4", queued = dir_ / "queued.mp4";
  {
    VideoWriter writer(plain, VideoFormat::mp4, 64, 48, 24);
    for (int f = 0; f < 30; ++f) writer.write_frame(gradient_frame(64, 48, f).data());
    writer.finish();
  }
  {
    QueuedVideoWriter writer(std::make_unique<VideoWriter>(queued, VideoFormat::mp4, 64, 48, 24));
    std::vector<std::uint8_t> frame;
    for (int f = 0; f < 30; ++f) {
      frame = gradient_frame(64, 48, f);
      writer.write_frame(frame);
    }
    EXPECT_FALSE(fs::exists(queued)) << "the real name appears only on finish()";
    writer.finish();
    EXPECT_EQ(writer.frames_written(), 30u);
    writer.finish();  // idempotent
  }
  EXPECT_EQ(ffprobe(queued).frames, 30);
  const auto a = file_bytes(plain), b = file_bytes(queued);
  EXPECT_GT(a.size(), 0u);
  EXPECT_TRUE(a == b) << "the videos differ (" << a.size() << " and " << b.size() << " bytes)";
}

TEST_F(VideoTest, QueuedWriterDestroyedWithoutFinishLeavesNothing) {
  {
    QueuedVideoWriter writer(
        std::make_unique<VideoWriter>(dir_ / "a.mp4", VideoFormat::mp4, 64, 48, 24));
    for (int f = 0; f < 5; ++f) writer.write_frame(gradient_frame(64, 48, f));
  }
  EXPECT_TRUE(entries().empty());
}

TEST_F(VideoTest, QueuedWriterRejectsAFrameOfTheWrongSize) {
  QueuedVideoWriter writer(
      std::make_unique<VideoWriter>(dir_ / "a.mp4", VideoFormat::mp4, 64, 48, 24));
  const std::string message =
      error_of<std::invalid_argument>([&] { writer.write_frame(gradient_frame(64, 46, 0)); });
  EXPECT_NE(message.find("expected 12288"), std::string::npos) << message;
}

TEST_F(VideoTest, QueuedWriterReportsFfmpegsErrorAndLeavesNothing) {
  VideoOptions options;
  options.x264_preset = "no-such-preset";
  const std::string message = error_of([&] {
    QueuedVideoWriter writer(
        std::make_unique<VideoWriter>(dir_ / "a.mp4", VideoFormat::mp4, 64, 48, 24, options));
    for (int f = 0; f < 200; ++f) writer.write_frame(gradient_frame(64, 48, f % 12));
    writer.finish();
  });
  EXPECT_NE(message.find("cannot write video"), std::string::npos) << message;
  EXPECT_NE(message.find("preset"), std::string::npos) << "ffmpeg's stderr is quoted: " << message;
  EXPECT_TRUE(entries().empty());
}

}  // namespace
