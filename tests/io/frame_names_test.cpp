#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/frame_names.hpp"
#include "io/png_writer.hpp"
#include "support/temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using namespace epviz::io;

TEST(FrameNames, ZeroPaddedToAtLeastFourDigits) {
  EXPECT_EQ(frame_file_name(42, 100), "frame_0042.png");
  EXPECT_EQ(frame_file_name(0, 1), "frame_0000.png");
  EXPECT_EQ(frame_file_name(9999, 10000), "frame_9999.png");
  EXPECT_EQ(frame_file_name(42, 10001), "frame_00042.png");  // last index 10000 has five digits
  EXPECT_EQ(frame_file_name(123456, 1000000), "frame_123456.png");
  EXPECT_EQ(frame_file_name(3, 10, "case_", ".ppm"), "case_0003.ppm");
  EXPECT_EQ(frame_number_width(1), 4);
  EXPECT_EQ(frame_number_width(10000), 4);
  EXPECT_EQ(frame_number_width(10001), 5);
  EXPECT_THROW(frame_file_name(100, 100), std::invalid_argument);
  EXPECT_THROW(frame_file_name(-1, 100), std::invalid_argument);
}

TEST(FrameNames, NamesSortInFrameOrder) {
  std::vector<std::string> names;
  for (int i = 0; i < 12000; i += 997) names.push_back(frame_file_name(i, 12000));
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
}

class PngComplete : public epviz::test::TempDirTest {
 protected:
  void SetUp() override {
    std::vector<std::uint8_t> rgba(17 * 9 * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(i * 7);
    good_ = encode_png_rgba(17, 9, rgba);
  }
  fs::path write(const std::string& name, const std::vector<std::uint8_t>& bytes) {
    return tmp_.write(name, std::string(bytes.begin(), bytes.end()));
  }
  std::vector<std::uint8_t> good_;
};

TEST_F(PngComplete, CompleteFileWrittenByTheWriterIsComplete) {
  std::vector<std::uint8_t> rgba(8 * 6 * 4, 90);
  write_png_rgba(dir_ / "frame_0000.png", 8, 6, rgba);
  EXPECT_TRUE(png_frame_complete(dir_ / "frame_0000.png"));
  EXPECT_TRUE(png_frame_complete(write("good.png", good_)));
}

TEST_F(PngComplete, TruncatedFilesAreNotComplete) {
  for (std::size_t keep : {std::size_t{0}, std::size_t{4}, std::size_t{8}, std::size_t{20},
                           good_.size() / 2, good_.size() - 12, good_.size() - 1}) {
    const std::vector<std::uint8_t> cut(good_.begin(),
                                        good_.begin() + static_cast<std::ptrdiff_t>(keep));
    EXPECT_FALSE(png_frame_complete(write("cut.png", cut)))
        << "kept " << keep << " of " << good_.size();
  }
}

TEST_F(PngComplete, GarbageIsNotComplete) {
  std::vector<std::uint8_t> text(200, 'x');
  EXPECT_FALSE(png_frame_complete(write("text.png", text)));
  std::vector<std::uint8_t> flipped = good_;
  flipped[flipped.size() / 2] ^= 0x40;  // a corrupted byte inside the image data: CRC mismatch
  EXPECT_FALSE(png_frame_complete(write("flipped.png", flipped)));
  std::vector<std::uint8_t> trailing = good_;
  trailing.push_back(0);  // something after IEND
  EXPECT_FALSE(png_frame_complete(write("trailing.png", trailing)));
  std::vector<std::uint8_t> no_signature(good_.begin() + 8, good_.end());
  EXPECT_FALSE(png_frame_complete(write("nosig.png", no_signature)));
}

TEST_F(PngComplete, MissingFileOrDirectoryIsNotComplete) {
  EXPECT_FALSE(png_frame_complete(dir_ / "frame_0001.png"));
  EXPECT_FALSE(png_frame_complete(dir_));
}

}  // namespace
