// Command-line values read strictly: all of the text, finite, in range; a
// mistake names the option and quotes the value on one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/bad_input.hpp"
#include "io/option_values.hpp"
#include "io/output_paths.hpp"
#include "support/errors.hpp"
#include "support/temp_dir.hpp"

namespace epviz {
namespace {

TEST(OptionValues, Numbers) {
  EXPECT_EQ(io::parse_number("--tol", "1e-3"), 1e-3);
  EXPECT_EQ(io::parse_number("--tol", "-2.5"), -2.5);
  for (const char* bad : {"", "1e-3x", " 1", "nan", "inf", "1e999"})
    EXPECT_EQ(test::error_of<io::BadInput>([&] { io::parse_number("--tol", bad); }),
              std::string("--tol: expected a finite number, got '") + bad + "'");
}

TEST(OptionValues, IntegersWithinTheirRange) {
  EXPECT_EQ(io::parse_integer("--port", "0", 0, 65535), 0);
  EXPECT_EQ(io::parse_integer("--port", "65535", 0, 65535), 65535);
  for (const char* bad : {"65536", "-1", "1.5", "", "8080 ", "0x10"})
    EXPECT_EQ(test::error_of<io::BadInput>([&] { io::parse_integer("--port", bad, 0, 65535); }),
              std::string("--port: expected an integer from 0 to 65535, got '") + bad + "'");
}

TEST(OptionValues, ThreeNumbers) {
  EXPECT_EQ(io::parse_vec3("--omega", "1,2.5,3e-1"), (std::array<double, 3>{1.0, 2.5, 0.3}));
  for (const char* bad : {"1,2", "1,2,3,4", "1,,3", "1,2,x", "", "1;2;3"})
    EXPECT_EQ(test::error_of<io::BadInput>([&] { io::parse_vec3("--omega", bad); }),
              std::string("--omega: expected three comma-separated finite numbers X,Y,Z, got '") +
                  bad + "'");
  // A value with a newline stays on one line of the message.
  const auto message = test::error_of<io::BadInput>([] { io::parse_vec3("--omega", "1\n2"); });
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(SeparateFiles, TwoSpellingsOfOneFileAreRefused) {
  test::TempDir dir;
  const auto file = (dir / "out.csv").string();
  std::filesystem::create_symlink(file, dir / "link.csv");
  const auto dotted = (dir.path() / "." / "out.csv").string();
  io::require_separate_files({},
                             {{"--csv", file}, {"--report-json", (dir / "report.json").string()}});
  io::require_separate_files({}, {{"--csv", "-"}, {"--report-json", "-"}});
  io::require_separate_files({}, {{"--csv", ""}, {"--report-json", ""}});
  for (const auto& other : {file, dotted, (dir / "link.csv").string()}) {
    const auto message = test::error_of<io::BadInput>([&] {
      io::require_separate_files({}, {{"--csv", file}, {"--report-json", other}});
    });
    EXPECT_EQ(message.rfind("--report-json: '", 0), 0u) << message;
    EXPECT_NE(message.find("the same file as --csv"), std::string::npos) << message;
  }
}

// Existing files are compared by device and inode: a hard link is the file.
TEST(SeparateFiles, AnOutputThatIsAnInputIsRefusedHowEverSpelled) {
  test::TempDir dir;
  const auto job = dir.write("job.json", "{}");
  std::filesystem::create_hard_link(job, dir / "hard.json");
  std::filesystem::create_symlink(job, dir / "soft.json");
  for (const auto& out :
       {job, dir / "hard.json", dir / "soft.json", dir.path() / "." / "job.json"}) {
    const auto message = test::error_of<io::BadInput>([&] {
      io::require_separate_files({{"--job", job.string()}}, {{"--csv", out.string()}});
    });
    EXPECT_EQ(message.rfind("--csv: '", 0), 0u) << message;
    EXPECT_NE(message.find("the same file as --job ('" + job.string() + "')"), std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  // Two hard links to one new output, and a file that is not there yet.
  const auto message = test::error_of<io::BadInput>([&] {
    io::require_separate_files(
        {}, {{"--csv", (dir / "hard.json").string()}, {"--h5", (dir / "soft.json").string()}});
  });
  EXPECT_EQ(message.rfind("--h5: ", 0), 0u) << message;
  io::require_separate_files({{"--job", job.string()}}, {{"--csv", (dir / "new.csv").string()}});
  EXPECT_EQ(test::slurp(job), "{}");
}

// Nothing replaces a character device: /dev/null may take every output.
TEST(SeparateFiles, CharacterDevicesAreNotCompared) {
  io::require_separate_files({{"--job", "/dev/null"}},
                             {{"--csv", "/dev/null"}, {"--report-json", "/dev/null"}});
}

}  // namespace
}  // namespace epviz
