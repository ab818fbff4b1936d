// --format of `epviz bench` and `epviz merge`: a bad value is refused before
// any work; `bench --format svg` writes every chart as a well-formed SVG and
// no PNG.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include "support/cli.hpp"

namespace epviz {
namespace {

using test::run_epviz;
using test::TempDir;

TEST(FigureFormatOption, BadValueIsRefusedBeforeAnyWork) {
  TempDir dir;
  const auto bench = run_epviz("bench --quick --format eps --out " + (dir / "o").string(), dir);
  test::expect_bad_input(bench,
                         "--format: 'eps' is not a figure format (expected png, svg or pdf)");
  EXPECT_EQ(bench.err.find("work-precision"), std::string::npos) << "a study ran: " << bench.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "o"));
  test::expect_bad_input(run_epviz("merge " + dir.path().string() + " --format jpg", dir),
                         "--format: 'jpg'");
}

TEST(FigureFormatOption, BenchWritesEveryChartAsSvg) {
  if (std::system("command -v python3 >/dev/null") != 0) GTEST_SKIP() << "no python3";
  TempDir dir;
  const auto out = dir / "charts";
  const auto r = run_epviz(
      "bench --quick --cases euler --format svg --gl nonsense-unused --out " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 2) << "--gl is still checked: " << r.err;
  const auto ok = run_epviz("bench --quick --cases euler --format svg --out " + out.string(), dir);
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  int svgs = 0;
  for (const auto& e : std::filesystem::directory_iterator(out)) {
    const auto name = e.path().filename().string();
    if (name == "bench.json") continue;
    EXPECT_EQ(e.path().extension(), ".svg") << name;
    const std::string parse =
        "python3 -c 'import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])' '" +
        e.path().string() + "' 2>&1";
    EXPECT_EQ(std::system(parse.c_str()), 0) << name << " is not well-formed XML";
    ++svgs;
  }
  EXPECT_GE(svgs, 5);
  EXPECT_NE(ok.out.find(std::to_string(svgs) + " charts written"), std::string::npos) << ok.out;
}

}  // namespace
}  // namespace epviz
