// --format of `epviz bench` and `epviz merge`: a bad value is refused before
// any work; `bench --format svg` writes every chart as a well-formed SVG and
// no PNG.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

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

// Runs the sweep `sweep_json` as one shard into dir/rows and merges it with
// --format pdf: the text pdftotext finds in the one atlas PDF, or "" (with a
// test failure) when something did not run.
std::string merged_atlas_text(const TempDir& dir, const std::string& sweep_json) {
  const auto sweep = dir.write("atlas.sweep.json", sweep_json);
  std::filesystem::create_directories(dir / "rows");
  const auto s = run_epviz("sweep " + sweep.string() + " --out " +
                               (dir / "rows/rows.jsonl").string() + " --shard 0/1 --quiet",
                           dir);
  EXPECT_EQ(s.exit_code, 0) << s.err;
  const auto m = run_epviz("merge " + (dir / "rows").string() + " --format pdf", dir);
  EXPECT_EQ(m.exit_code, 0) << m.err;
  std::vector<std::filesystem::path> pdfs, pngs;
  for (const auto& e : std::filesystem::directory_iterator(dir / "rows")) {
    if (e.path().extension() == ".pdf") pdfs.push_back(e.path());
    if (e.path().extension() == ".png") pngs.push_back(e.path());
  }
  EXPECT_TRUE(pngs.empty()) << "a PNG drawn besides the PDF";
  if (pdfs.size() != 1) {
    ADD_FAILURE() << pdfs.size() << " PDFs: " << m.out;
    return "";
  }
  const auto text = dir / "atlas.txt";
  EXPECT_EQ(std::system(("pdftotext " + pdfs[0].string() + " " + text.string()).c_str()), 0);
  return test::slurp(text);
}

// `merge --format pdf` writes the sweep's atlas as a PDF whose title is text,
// and draws no PNG.
TEST(FigureFormatOption, MergeWritesTheAtlasAsPdf) {
  if (std::system("command -v pdftotext >/dev/null") != 0) GTEST_SKIP() << "no pdftotext";
  TempDir dir;
  const std::string words = merged_atlas_text(dir, R"({
    "simulation": {"case": "generic", "t_end": 5, "samples": 5, "max_drift": 0.1},
    "axes": [{"field": "method", "values": ["rk4", "midpoint"]},
             {"field": "step", "values": [1.0, 0.25, 0.05]},
             {"field": "energy", "values": [1.5, 10]}],
    "atlas": [{"metric": "largest_stable:step", "x": "energy", "y": "method"}]})");
  for (const char* w : {"largest stable step", "energy", "method", "rk4", "midpoint"})
    EXPECT_NE(words.find(w), std::string::npos) << w << " not in\n" << words;
}

// A merged FTLE atlas says at which T, with which window and separation its
// exponents were measured, and names its axes by symbol.
TEST(FigureFormatOption, AMergedFtleAtlasCaptionNamesTheWindow) {
  if (std::system("command -v pdftotext >/dev/null") != 0) GTEST_SKIP() << "no pdftotext";
  TempDir dir;
  const std::string words = merged_atlas_text(dir, R"({
    "simulation": {"case": "generic", "t_end": 2, "samples": 2, "normalize_gamma": true,
                   "gamma": [0, 0, 1]},
    "axes": [{"field": "gamma[1]", "from": -0.5, "to": 0.5, "count": 2},
             {"field": "gamma[0]", "from": -0.5, "to": 0.5, "count": 2}],
    "ftle": {"separation": 1e-8, "window": 0.5},
    "atlas": [{"metric": "ftle", "x": "gamma[0]", "y": "gamma[1]"}]})");
  for (const char* w : {"window", "T = 2", "γ"})
    EXPECT_NE(words.find(w), std::string::npos) << w << " not in\n" << words;
}

// A sweep that asks for λ(T) curves gets them as one chart from merge, each
// point's line named by its axis values, with the ln T / T guide, and the
// FTLE's window and separation on the time axis.
TEST(FigureFormatOption, MergeDrawsTheFtleCurvesOfASweepThatAsksForThem) {
  if (std::system("command -v pdftotext >/dev/null") != 0) GTEST_SKIP() << "no pdftotext";
  TempDir dir;
  const std::string words = merged_atlas_text(dir, R"({
    "simulation": {"t_end": 20, "samples": 1, "tol": 1e-10,
                   "omega": [1.0, 0.8, 0.6], "gamma": [0.72, 0.6, 0.34], "normalize_gamma": true},
    "axes": [{"field": "case", "values": ["lagrange", "generic"]}],
    "ftle": {"separation": 1e-8, "window": 1, "curve": true},
    "self_check": {"threshold": 1}})");
  for (const char* w : {"λ(T)", "case lagrange", "case generic", "ln T / T", "window 1"})
    EXPECT_NE(words.find(w), std::string::npos) << w << " not in\n" << words;
}

}  // namespace
}  // namespace epviz
