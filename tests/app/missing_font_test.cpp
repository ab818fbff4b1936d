// A machine without the font draws nothing: `epviz render` fails (exit 1) with
// one line naming the Debian package, instead of drawing every label with
// another font (which a golden made with DejaVu would then reject for no
// visible reason). The font is hidden by mounting an empty tmpfs over its
// folder in a private mount namespace (unshare -m), which needs root; where
// that is not permitted the test skips and says so.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli.hpp"
#include "support/render_job.hpp"
#include "support/temp_dir.hpp"

namespace epviz::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFontDir = "/usr/share/fonts/truetype/dejavu";

bool can_hide_the_font() {
  return fs::is_directory(kFontDir) && std::system("unshare -m true >/dev/null 2>&1") == 0;
}

// `epviz render JOB` with the font's folder hidden, and `env` before it.
CliResult render_without_the_font(const TempDir& dir, const std::string& env = "") {
  std::ofstream(dir / "job.json") << small_render_job(dir / "out", 2, 1.0).dump();
  const std::string inner = std::string("mount -t tmpfs none ") + kFontDir + " && exec env " + env +
                            " " + EPVIZ_BINARY + " render " + (dir / "job.json").string();
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd =
      "unshare -m sh -c '" + inner + "' >" + out.string() + " 2>" + err.string() + " </dev/null";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

std::size_t pngs_in(const fs::path& dir) {
  std::size_t n = 0;
  std::error_code error;
  for (const auto& e : fs::directory_iterator(dir, error))
    if (e.path().extension() == ".png") ++n;
  return n;
}

TEST(MissingFont, RenderFailsNamingThePackage) {
  if (!can_hide_the_font()) GTEST_SKIP() << "unshare -m is not permitted here (it needs root)";
  TempDir dir;
  const auto r = render_without_the_font(dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("fonts-dejavu-core"), std::string::npos) << r.err;
  EXPECT_EQ(line_count(r.err), 1u) << r.err;
  EXPECT_EQ(pngs_in(dir / "out"), 0u);
}

TEST(MissingFont, TheBuiltinFontIsAnExplicitChoice) {
  if (!can_hide_the_font()) GTEST_SKIP() << "unshare -m is not permitted here (it needs root)";
  TempDir dir;
  const auto r = render_without_the_font(dir, "EPVIZ_FONT=builtin");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(pngs_in(dir / "out"), 2u);
}

TEST(MissingFont, AFontFileThatIsNotThereIsNamed) {
  TempDir dir;
  std::ofstream(dir / "job.json") << small_render_job(dir / "out", 2, 1.0).dump();
  const std::string missing = (dir / "no-such-font.ttf").string();
  setenv("EPVIZ_FONT", missing.c_str(), 1);
  const auto r = run_epviz("render " + (dir / "job.json").string(), dir);
  unsetenv("EPVIZ_FONT");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  EXPECT_EQ(pngs_in(dir / "out"), 0u);
}

}  // namespace
}  // namespace epviz::test
