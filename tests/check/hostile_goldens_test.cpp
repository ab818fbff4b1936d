// Goldens and golden.json come from version control, so they are hostile
// input: a decompression bomb, links, FIFOs, damaged files and a golden.json
// that does not hold a golden record. Each is refused or reported, cheaply,
// without hanging and without writing through a link.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <zlib.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

#include "check/golden_record.hpp"
#include "check/job_check.hpp"
#include "io/bad_input.hpp"
#include "support/cli.hpp"
#include "test_images.hpp"

namespace epviz::check {
namespace {

namespace fs = std::filesystem;

void put_chunk(std::ofstream& out, const char* type, const std::string& data) {
  const auto be32 = [&](std::uint32_t v) {
    const char b[4] = {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    out.write(b, 4);
  };
  be32(std::uint32_t(data.size()));
  const std::string body = std::string(type, 4) + data;
  out.write(body.data(), std::streamsize(body.size()));
  be32(std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
}

// A valid 1-bit grey PNG of side x side black pixels: tens of kilobytes on
// disk, side² pixels once decoded.
void write_png_bomb(const fs::path& file, std::uint32_t side) {
  std::string ihdr(13, '\0');
  for (int k = 0; k < 4; ++k) ihdr[k] = ihdr[4 + k] = char(side >> (24 - 8 * k));
  ihdr[8] = 1;  // bit depth; colour type 0 (grey), no interlace
  z_stream z{};
  ASSERT_EQ(deflateInit(&z, 9), Z_OK);
  std::vector<unsigned char> row(1 + (side + 7) / 8, 0), chunk(1 << 16);
  std::string idat;
  for (std::uint32_t y = 0; y <= side; ++y) {
    z.next_in = row.data();
    z.avail_in = y < side ? uInt(row.size()) : 0;
    do {
      z.next_out = chunk.data();
      z.avail_out = uInt(chunk.size());
      deflate(&z, y < side ? Z_NO_FLUSH : Z_FINISH);
      idat.append(reinterpret_cast<char*>(chunk.data()), chunk.size() - z.avail_out);
    } while (z.avail_out == 0);
  }
  deflateEnd(&z);
  std::ofstream out(file, std::ios::binary);
  out.write("\x89PNG\r\n\x1a\n", 8);
  put_chunk(out, "IHDR", ihdr);
  put_chunk(out, "IDAT", idat);
  put_chunk(out, "IEND", "");
}

long peak_rss_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

class HostileGoldens : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(dir_ / "kov.json") << "{}\n";
    job_ = {.shown = "jobs/kov.json",
            .job_file = dir_ / "kov.json",
            .golden_dir = dir_ / "golden" / "kov",
            .frame_count = 10,
            .frames = {0},
            .width = 40,
            .height = 30};
    fs::create_directories(job_.golden_dir);
  }
  CheckSettings settings() const {
    CheckSettings s;
    s.environment = {"llvmpipe", "4.5", "builtin", ""};
    s.update_command = [](const GoldenJob&, const std::vector<int>&) { return "update"; };
    return s;
  }
  JobOutcome compare(const TestImage& image) {
    return JobChecker(settings())
        .compare(job_, 0, std::vector<ImageView>{image.view()}, std::nullopt);
  }
  std::string bad_input_message() {
    try {
      check_golden_inputs(job_, false);
    } catch (const io::BadInput& e) {
      return e.what();
    }
    return "(accepted)";
  }
  fs::path record() const { return job_.golden_dir / "golden.json"; }

  test::TempDir dir_;
  GoldenJob job_;
};

TEST_F(HostileGoldens, ABombIsReportedMisSizedWithoutDecoding) {
  write_png_bomb(job_.golden_path(0), 23000);
  ASSERT_LT(fs::file_size(job_.golden_path(0)), 200u * 1024);
  const long rss_before = peak_rss_kib();
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(bad_input_message(), "(accepted)");
  const auto out = compare(flat_image(40, 30, 1, 2, 3));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0);
  EXPECT_LT(peak_rss_kib() - rss_before, 100 * 1024);
  EXPECT_NE(out.results[0].problem.find("is 23000x23000 but the frame is 40x30"), std::string::npos)
      << out.results[0].problem;
}

TEST_F(HostileGoldens, ADamagedGoldenIsSaidToBeDamaged) {
  // A PNG header of the right size with no image data after it.
  const auto image = flat_image(40, 30, 1, 2, 3);
  JobChecker(settings()).update(job_, std::vector<ImageView>{image.view()}, std::nullopt);
  const auto full = test::slurp(job_.golden_path(0));
  std::ofstream(job_.golden_path(0), std::ios::binary) << full.substr(0, 40);
  const auto out = compare(image);
  EXPECT_FALSE(out.results[0].passed);
  EXPECT_NE(out.results[0].problem.find("is damaged"), std::string::npos) << out.results[0].problem;
  // Not a PNG at all: refused before any work.
  std::ofstream(job_.golden_path(0)) << "not a png";
  EXPECT_NE(bad_input_message().find("frame_0000.png: a damaged golden"), std::string::npos)
      << bad_input_message();
}

TEST_F(HostileGoldens, LinksAndFifosAreRefusedBeforeWork) {
  const auto victim = dir_ / "victim.txt";
  std::ofstream(victim) << "keep me";
  fs::create_symlink(victim, job_.golden_path(0));
  EXPECT_NE(bad_input_message().find("frame_0000.png: a golden is a symbolic link"),
            std::string::npos);
  const auto image = flat_image(40, 30, 1, 2, 3);
  EXPECT_THROW(
      JobChecker(settings()).update(job_, std::vector<ImageView>{image.view()}, std::nullopt),
      io::BadInput);
  EXPECT_EQ(test::slurp(victim), "keep me");
  fs::remove(job_.golden_path(0));
  ASSERT_EQ(mkfifo(job_.golden_path(0).c_str(), 0600), 0);
  EXPECT_NE(bad_input_message().find("frame_0000.png: a golden is not a regular file"),
            std::string::npos);
  fs::remove(job_.golden_path(0));
  fs::create_symlink(victim, record());
  EXPECT_NE(bad_input_message().find("golden.json: not a regular file"), std::string::npos);
  EXPECT_THROW(
      JobChecker(settings()).update(job_, std::vector<ImageView>{image.view()}, std::nullopt),
      io::BadInput);
  EXPECT_EQ(test::slurp(victim), "keep me");
  fs::remove(record());
  ASSERT_EQ(mkfifo(record().c_str(), 0600), 0);
  EXPECT_NE(bad_input_message().find("golden.json: not a regular file"), std::string::npos);
  fs::remove(record());
  fs::create_directory(record());
  EXPECT_NE(bad_input_message().find("golden.json: not a regular file"), std::string::npos);
}

TEST_F(HostileGoldens, AGoldenFolderUnderAFileIsRefused) {
  fs::remove_all(dir_ / "golden");
  std::ofstream(dir_ / "golden") << "a file";
  EXPECT_NE(bad_input_message().find("golden: the golden folder"), std::string::npos)
      << bad_input_message();
}

TEST_F(HostileGoldens, AGoldenJsonThatIsNoRecordNamesTheKey) {
  const auto message = [&](const std::string& text) {
    std::ofstream(record()) << text;
    return bad_input_message();
  };
  const std::string ok = R"("epviz_version": "1", "gl_renderer": "r", "gl_version": "v")";
  EXPECT_EQ(message("{" + ok + "}"), "(accepted)");
  EXPECT_NE(message("{" + ok + R"(, "frames": [-5]})").find("golden.json: frames: -5 is not"),
            std::string::npos);
  EXPECT_NE(message(R"({"epviz_version": "1", "gl_renderer": 7})").find("gl_renderer: missing"),
            std::string::npos);
  EXPECT_NE(message("[").find("golden.json: not JSON"), std::string::npos);
  const std::string huge = "{" + ok + R"(, "job_file": ")" + std::string(2 << 20, 'x') + "\"}";
  const auto m = message(huge);
  EXPECT_NE(m.find("larger than 1 MiB"), std::string::npos);
  EXPECT_LT(m.size(), 400u);
}

TEST_F(HostileGoldens, TheRecordedRendererIsEscapedAndBounded) {
  nlohmann::json j = {{"epviz_version", "1"},
                      {"gl_renderer", "x\n::error::pwned\x1b[31m" + std::string(100000, 'y')},
                      {"gl_version", "v"}};
  std::ofstream(record()) << j.dump();
  const auto out = compare(flat_image(40, 30, 1, 2, 3));
  ASSERT_EQ(out.warnings.size(), 1u);
  const auto& w = out.warnings[0];
  EXPECT_EQ(w.find('\n'), std::string::npos);
  EXPECT_EQ(w.find('\x1b'), std::string::npos);
  EXPECT_LT(w.size(), 1000u);
  EXPECT_NE(w.find("x\\n::error::pwned"), std::string::npos) << w;
}

}  // namespace
}  // namespace epviz::check
