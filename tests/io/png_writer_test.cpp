#include <gtest/gtest.h>

#include <stb/stb_image.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/png_writer.hpp"
#include "io/temp_name.hpp"
#include "support/temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using namespace epviz::io;

class PngFiles : public epviz::test::TempDirTest {
 protected:
  bool has_temporaries() const {
    for (const auto& entry : fs::directory_iterator(dir_))
      if (parse_temporary_name(entry.path().filename().string())) return true;
    return false;
  }
};

// A picture with gradients, hard edges and partial alpha.
std::vector<std::uint8_t> test_pattern(int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      auto* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      p[0] = static_cast<std::uint8_t>(x * 255 / std::max(width - 1, 1));
      p[1] = static_cast<std::uint8_t>(y * 255 / std::max(height - 1, 1));
      p[2] = ((x / 8 + y / 8) % 2) ? 230 : 20;
      p[3] = static_cast<std::uint8_t>(x < width / 2 ? 255 : 128);
    }
  return rgba;
}

std::vector<std::uint8_t> read_png(const fs::path& path, int& width, int& height) {
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
  if (data == nullptr) return {};
  std::vector<std::uint8_t> pixels(data, data + static_cast<std::size_t>(width) * height * 4);
  stbi_image_free(data);
  return pixels;
}

TEST_F(PngFiles, PngRoundTripIsLossless) {
  const int width = 67, height = 41;  // odd sizes catch stride mistakes
  const auto pixels = test_pattern(width, height);
  for (int level : {1, 6, 9})
    for (int filter : {-1, 0, 2, 4}) {
      const auto path =
          dir_ / ("round_trip_" + std::to_string(level) + "_" + std::to_string(filter) + ".png");
      write_png_rgba(path, width, height, pixels, {.compression_level = level, .filter = filter});
      int w = 0, h = 0;
      const auto back = read_png(path, w, h);
      ASSERT_EQ(w, width);
      ASSERT_EQ(h, height);
      EXPECT_EQ(back, pixels) << "level " << level << " filter " << filter;
    }
  EXPECT_FALSE(has_temporaries());
}

TEST_F(PngFiles, WrongBufferSizeIsRejected) {
  std::vector<std::uint8_t> pixels(10);
  EXPECT_THROW(write_png_rgba(dir_ / "bad.png", 4, 4, pixels), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir_ / "bad.png"));
}

TEST_F(PngFiles, UnwritableDirectoryGivesAClearErrorAndLeavesNothing) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  const auto locked = dir_ / "locked";
  fs::create_directories(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  const auto pixels = test_pattern(8, 8);
  try {
    write_png_rgba(locked / "frame_0001.png", 8, 8, pixels);
    FAIL() << "writing into a read-only directory must throw";
  } catch (const FileWriteError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("frame_0001.png"), std::string::npos) << message;
    EXPECT_NE(message.find("Permission denied"), std::string::npos) << message;
  }
  fs::permissions(locked, fs::perms::owner_all);
  EXPECT_TRUE(fs::is_empty(locked));
}

TEST_F(PngFiles, MissingDirectoryGivesAClearError) {
  const auto pixels = test_pattern(8, 8);
  try {
    write_png_rgba(dir_ / "no" / "such" / "frame.png", 8, 8, pixels);
    FAIL() << "writing into a missing directory must throw";
  } catch (const FileWriteError& error) {
    EXPECT_NE(std::string(error.what()).find("No such file or directory"), std::string::npos)
        << error.what();
  }
}

TEST_F(PngFiles, AtomicFileIsInvisibleUntilCommitted) {
  const auto target = dir_ / "data.json";
  {
    AtomicFile file(target);
    file.write(std::string_view("{\"partial\": "));
    EXPECT_FALSE(fs::exists(target)) << "nothing under the real name before commit";
    EXPECT_TRUE(fs::exists(temporary_path_for(target)));
    // Destroyed without commit (as when an exception unwinds): no file at all.
  }
  EXPECT_FALSE(fs::exists(target));
  EXPECT_FALSE(has_temporaries());
}

TEST_F(PngFiles, AtomicWriteReplacesTheOldFileWhole) {
  const auto target = dir_ / "data.txt";
  write_file_atomically(target, std::string_view("old contents, rather long"));
  write_file_atomically(target, std::string_view("new"), true);
  std::ifstream in(target);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "new");
  EXPECT_FALSE(has_temporaries());
}

TEST_F(PngFiles, TemporaryNameCarriesThePid) {
  EXPECT_EQ(temporary_path_for(dir_ / "a.png").filename().string(),
            "a.png" + temporary_suffix(::getpid()));
}

TEST_F(PngFiles, AsyncWriterWritesEveryFrame) {
  const int width = 40, height = 30, frames = 24;
  const auto pixels = test_pattern(width, height);
  AsyncPngWriter writer({.threads = 2, .max_queued = 3, .png = {}});
  for (int i = 0; i < frames; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    auto frame = pixels;
    frame[0] = static_cast<std::uint8_t>(i);  // each frame distinct
    writer.submit(dir_ / name, width, height, std::move(frame));
  }
  writer.close();
  EXPECT_EQ(writer.frames_written(), static_cast<std::size_t>(frames));
  for (int i = 0; i < frames; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    int w = 0, h = 0;
    const auto back = read_png(dir_ / name, w, h);
    ASSERT_EQ(back.size(), pixels.size()) << name;
    EXPECT_EQ(back[0], i);
  }
  EXPECT_FALSE(has_temporaries());
}

TEST_F(PngFiles, AsyncWriterReportsTheFirstError) {
  AsyncPngWriter writer({.threads = 1, .max_queued = 2, .png = {}});
  writer.submit(dir_ / "missing" / "frame.png", 4, 4, test_pattern(4, 4));
  EXPECT_THROW(writer.wait_idle(), FileWriteError);
  writer.close();  // the error was reported once; closing is clean
}

}  // namespace
