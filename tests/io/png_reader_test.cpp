// io::read_png_size reads a PNG's size from its header alone, and
// io::read_png_rgba refuses what is not a regular file or claims more pixels
// than it may decode.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "io/png_reader.hpp"
#include "io/png_writer.hpp"
#include "support/temp_dir.hpp"

namespace epviz::io {
namespace {

namespace fs = std::filesystem;

TEST(PngReader, TheSizeComesFromTheHeader) {
  test::TempDir dir;
  const auto file = dir / "a.png";
  const std::vector<std::uint8_t> rgba(7 * 5 * 4, 200);
  write_png_rgba(file, 7, 5, rgba);
  const auto size = read_png_size(file);
  ASSERT_TRUE(size);
  EXPECT_EQ(size->width, 7);
  EXPECT_EQ(size->height, 5);
  // A header alone, claiming 4 billion pixels (bytes written by hand: the
  // signature, then IHDR's length, type, width and height, big-endian).
  const auto huge = dir / "huge.png";
  std::ofstream(huge, std::ios::binary)
      .write("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\1\0\0\0\1\0\0\x08\x06\0\0\0", 29);
  const auto claimed = read_png_size(huge);
  ASSERT_TRUE(claimed);
  EXPECT_EQ(claimed->width, 65536);
  EXPECT_EQ(claimed->height, 65536);
  EXPECT_FALSE(read_png_rgba(huge));
  std::ofstream(dir / "text.png") << "hello, this is not a PNG file at all";
  EXPECT_FALSE(read_png_size(dir / "text.png"));
}

TEST(PngReader, AChunkLongerThanTheFileIsNotDecoded) {
  test::TempDir dir;
  const auto file = dir / "a.png";
  const std::vector<std::uint8_t> rgba(8 * 8 * 4, 100);
  write_png_rgba(file, 8, 8, rgba);
  ASSERT_TRUE(read_png_rgba(file));
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // The chunk after IHDR (8 + 25 bytes in) claims 2 GB of data the file does
  // not have; the decoder would grow its buffer to that before reading. (Not
  // decoded either way; that nothing is allocated for it is held by the fuzz
  // target, whose corpus has the file that found it and whose malloc limit
  // fails on it: fuzz/corpus/fuzz_golden_reader/chunk_longer_than_file.png.)
  const std::size_t second = 8 + 25;
  ASSERT_GT(bytes.size(), second + 8);
  bytes.replace(second, 4, "\x7f\xff\xff\x00", 4);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
  EXPECT_FALSE(read_png_rgba(file));
}

TEST(PngReader, ImageDataThatDoesNotEndIsNotDecoded) {
  // The file libFuzzer found (fuzz/corpus/fuzz_golden_reader/cut_image_data.png):
  // a 4 x 3 image whose zlib stream is cut short, then a second IHDR and
  // IDAT. stb_image's inflater read zeros past the stream's end and kept
  // decoding them, doubling its buffer up to 2 GB.
  test::TempDir dir;
  const auto file = dir / "cut.png";
  const std::string bytes(
      "\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\0\x04\0\0\0\x03\x08\x06\0\0\0\xb4\xf4\xae\xc6"
      "\0\0\0\x2aIDAT\x78\xda\x15\xc8\x31\x01\0\x20\x10\xc4\x0d\x0a\x1a\x0a\0\0\0\x0dIHDR"
      "\0\0\0\x04\0\0\0\x03\x08\x06\0\0\0\xb4\xf4\xae\xc6\0\0\0\x2aIDAT\0\0\x2aIDAT\x78\xda\0",
      98);
  std::ofstream(file, std::ios::binary) << bytes;
  // Not decoded either way (stb fails once it has grown); that nothing is
  // allocated for it is held by the fuzz target, which replays its corpus
  // under a malloc limit of 2 GB and failed on this file before.
  EXPECT_FALSE(read_png_rgba(file));
}

TEST(PngReader, ImagesOverTheCapAreNotDecoded) {
  test::TempDir dir;
  const auto file = dir / "a.png";
  const std::vector<std::uint8_t> rgba(8 * 8 * 4, 100);
  write_png_rgba(file, 8, 8, rgba);
  EXPECT_TRUE(read_png_rgba(file, 64));
  EXPECT_FALSE(read_png_rgba(file, 63));
}

TEST(PngReader, SizesWhoseProductOverflowsAreRefused) {
  test::TempDir dir;
  // 4294967295 x 4294967295 (the largest a header can hold): the product of
  // the two does not fit in 64 bits, which UBSan reported before the check
  // was a division. And zero by anything, which is no image.
  for (const char* size : {"\xff\xff\xff\xff\xff\xff\xff\xff", "\0\0\0\0\0\0\0\x08"}) {
    const auto file = dir / "claims.png";
    std::string bytes("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
    bytes.append(size, 8);
    bytes.append("\x08\x06\0\0\0", 5);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    ASSERT_TRUE(read_png_size(file));
    EXPECT_FALSE(read_png_rgba(file));
    EXPECT_FALSE(read_png_rgba(file, std::numeric_limits<std::int64_t>::max()));
  }
}

TEST(PngReader, AFifoIsNotOpened) {
  test::TempDir dir;
  const auto fifo = dir / "f.png";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // Opening a FIFO nobody writes would block forever.
  EXPECT_FALSE(read_png_size(fifo));
  EXPECT_FALSE(read_png_rgba(fifo));
}

}  // namespace
}  // namespace epviz::io
