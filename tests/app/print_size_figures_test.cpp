// Chart figures at a printed size (--figure-width, --font-size, --dpi, and a
// section file's "figure_width", "font_size", "dpi"): a PDF page as wide as
// asked, its text at least 6 pt tall and no word drawn over another, read
// back by poppler (support/pdf_words.hpp); a PNG that many inches at the
// dpi; and bad values refused before any work.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "io/png_reader.hpp"
#include "support/cli.hpp"
#include "support/pdf_words.hpp"

namespace epviz::test {
namespace {

namespace fs = std::filesystem;

constexpr double kColumnPt = 85.0 / 25.4 * 72.0;  // 85 mm: 240.94 pt
// pdftotext's box of a word is the font's size tall (7.99 pt at 8 pt): text
// under 6 pt tall would be smaller than a journal allows.
constexpr double kLeastWordPt = 6.0;

// The page is `width_pt` wide (within half a point: the layout rounds the
// width to whole units of 1/dpi inch), every word is on it, at least 6 pt
// tall, and none overlaps another; the words, for more checks.
std::vector<PdfWord> expect_printed(const fs::path& pdf, double width_pt) {
  EXPECT_TRUE(fs::exists(pdf)) << pdf;
  if (!fs::exists(pdf)) return {};
  const auto [page_width, page_height] = pdf_page_size_pt(pdf);
  EXPECT_NEAR(page_width, width_pt, 0.5) << pdf;
  const auto words = pdf_words(pdf);
  EXPECT_GT(words.size(), 3u) << pdf;
  for (const auto& w : words) {
    EXPECT_GE(w.height(), kLeastWordPt) << pdf.filename() << ": '" << w.text << "'";
    // On the page, not cut off at its edge.
    EXPECT_TRUE(w.x0 >= -0.5 && w.x1 <= page_width + 0.5 && w.y0 >= -0.5 &&
                w.y1 <= page_height + 0.5)
        << pdf.filename() << ": '" << w.text << "' at (" << w.x0 << ", " << w.y0 << ")-(" << w.x1
        << ", " << w.y1 << ") is off the " << page_width << " x " << page_height << " pt page";
  }
  for (const auto& [a, b] : overlapping_words(words))
    ADD_FAILURE() << pdf.filename() << ": '" << a.text << "' (" << a.x0 << ", " << a.y0
                  << ") overlaps '" << b.text << "' (" << b.x0 << ", " << b.y0 << ")";
  return words;
}

bool has_word(const std::vector<PdfWord>& words, const std::string& text) {
  for (const auto& w : words)
    if (w.text.find(text) != std::string::npos) return true;
  return false;
}

std::string section_file(const TempDir& d, const std::string& extra) {
  return R"({"case": "kovalevskaya", "level": {"energy": 2, "area": 0.5}, "orbits": 3,
    "crossings": 6, "csv": ")" +
         (d / "s.csv").string() + R"(", "pdf": ")" + (d / "s.pdf").string() + "\"" + extra + "}";
}

TEST(PrintSizeFigures, DiagramPdfIsAColumnWideWithPrintableText) {
  if (!have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
  TempDir d;
  const auto r = run_epviz(
      "diagram --case kovalevskaya --area 0.5 --samples 3000 --format pdf "
      "--figure-width 85mm --out " +
          (d / "o").string(),
      d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto words = expect_printed(d / "o/diagram.pdf", kColumnPt);
  EXPECT_TRUE(has_word(words, "K")) << "the y axis' label";
}

TEST(PrintSizeFigures, EveryBenchChartPdfIsAColumnWideWithPrintableText) {
  if (!have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
  TempDir d;
  const auto out = d / "charts";
  const auto r = run_epviz(
      "bench --quick --cases kovalevskaya --format pdf --figure-width 85mm --out " + out.string(),
      d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int pdfs = 0;
  for (const auto& e : fs::directory_iterator(out))
    if (e.path().extension() == ".pdf") {
      expect_printed(e.path(), kColumnPt);
      ++pdfs;
    }
  EXPECT_GE(pdfs, 5);
  // The drift chart names the integrals it follows by their symbols.
  const auto drift = pdf_words(out / "drift_kovalevskaya.pdf");
  for (const char* symbol : {"C₁", "K", "|γ|²"})
    EXPECT_TRUE(has_word(drift, symbol)) << symbol << " not in the drift chart";
}

// Larger type on a narrower page: long titles and notes wrap rather than
// run off the page.
TEST(PrintSizeFigures, BenchChartsWithLargerTypeStillFitTheirPage) {
  if (!have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
  TempDir d;
  const auto out = d / "charts";
  const auto r = run_epviz(
      "bench --quick --cases kovalevskaya --format pdf --figure-width 3.5in "
      "--font-size 10 --out " +
          out.string(),
      d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int pdfs = 0;
  for (const auto& e : fs::directory_iterator(out))
    if (e.path().extension() == ".pdf") {
      for (const auto& w : expect_printed(e.path(), 252.0))
        EXPECT_GE(w.height(), 9.5) << e.path().filename() << ": '" << w.text << "' (10 pt type)";
      ++pdfs;
    }
  EXPECT_GE(pdfs, 5);
}

TEST(PrintSizeFigures, BenchPngIsThatManyInchesAtTheDpi) {
  TempDir d;
  const auto out = d / "charts";
  const auto r = run_epviz(
      "bench --quick --cases euler --figure-width 3.5in --dpi 200 --out " + out.string(), d);
  if (r.exit_code != 0 && r.err.find("GL") != std::string::npos) GTEST_SKIP() << "no GL: " << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto size = io::read_png_size(out / "work_precision_euler.png");
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, 700);  // 3.5 in at 200 dpi
}

TEST(PrintSizeFigures, SectionPdfFromTheFileKeysAndTheOptionsOverThem) {
  if (!have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
  TempDir d;
  const auto file = d.write("s.section.json", section_file(d, R"(, "figure_width": "85mm",
    "font_size": 8, "dpi": 300)"));
  const auto r = run_epviz("section " + file.string() + " -j 2", d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_printed(d / "s.pdf", kColumnPt);
  // The command line's width wins over the file's.
  const auto wide = run_epviz("section " + file.string() + " -j 2 --figure-width 3.5in", d);
  ASSERT_EQ(wide.exit_code, 0) << wide.err;
  expect_printed(d / "s.pdf", 252.0);
}

TEST(PrintSizeFigures, SectionPanelsSideBySideShareTheWidthAsked) {
  if (!have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
  TempDir d;
  const auto file =
      d.write("s.section.json", section_file(d, R"(, "methods": [{"method": "rk4", "step": 0.05},
        {"method": "dop853", "tol": 1e-9}], "max_drift": 0.1)"));
  const auto r = run_epviz("section " + file.string() + " -j 2 --figure-width 170mm", d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto words = expect_printed(d / "s.pdf", 170.0 / 25.4 * 72.0);
  EXPECT_TRUE(has_word(words, "rk4")) << "the first panel's title";
  EXPECT_TRUE(has_word(words, "dop853")) << "the second panel's title";
}

TEST(PrintSizeFigures, MergedAtlasPdfIsAColumnWideWithPrintableText) {
  if (!have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
  TempDir d;
  const auto sweep = d.write("atlas.sweep.json", R"({
    "simulation": {"case": "generic", "t_end": 5, "samples": 5, "max_drift": 0.1},
    "axes": [{"field": "method", "values": ["rk4", "midpoint"]},
             {"field": "step", "values": [1.0, 0.25, 0.05]},
             {"field": "energy", "values": [1.5, 10]}],
    "atlas": [{"metric": "largest_stable:step", "x": "energy", "y": "method"}]})");
  fs::create_directories(d / "rows");
  const auto s = run_epviz("sweep " + sweep.string() + " --out " +
                               (d / "rows/rows.jsonl").string() + " --shard 0/1 --quiet",
                           d);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto m =
      run_epviz("merge " + (d / "rows").string() + " --format pdf --figure-width 85mm", d);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  int pdfs = 0;
  for (const auto& e : fs::directory_iterator(d / "rows"))
    if (e.path().extension() == ".pdf") {
      const auto words = expect_printed(e.path(), kColumnPt);
      EXPECT_TRUE(has_word(words, "midpoint")) << "a row's name";
      ++pdfs;
    }
  EXPECT_EQ(pdfs, 1);
}

// Three methods' panels in a column 85 mm wide would be 26 mm each: they go
// one under another instead, each the column's width.
TEST(PrintSizeFigures, SectionPanelsTooNarrowSideBySideGoOnMoreRows) {
  if (!have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
  TempDir d;
  const auto file = d.write("s.section.json", section_file(d, R"(, "methods": [
        {"method": "rk4", "step": 0.05}, {"method": "dop853", "tol": 1e-9},
        {"method": "splitting", "step": 0.05}], "max_drift": 0.1, "figure_width": "85mm")"));
  const auto r = run_epviz("section " + file.string() + " -j 2", d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto words = expect_printed(d / "s.pdf", kColumnPt);
  EXPECT_GT(pdf_page_size_pt(d / "s.pdf").second, 2.5 * kColumnPt) << "not stacked";
  for (const char* method : {"rk4", "dop853", "splitting"})
    EXPECT_TRUE(has_word(words, method)) << method << "'s panel";
}

// Each bad value: exit 2, one line naming the option and what is allowed,
// before any work, nothing written.
TEST(PrintSizeFigures, BadSizesAreRefusedBeforeAnyWork) {
  TempDir d;
  const std::vector<std::pair<std::string, std::string>> refused{
      {"--figure-width 85", "--figure-width: expected a length such as 85mm"},
      {"--figure-width 0.1in", "--figure-width: '0.1in' is outside"},
      {"--figure-width 85mm --font-size 2", "--font-size: '2' is outside 5 pt to 24 pt"},
      {"--figure-width 85mm --dpi 10", "--dpi: '10' is outside 72 dpi to 1200 dpi"},
      {"--font-size 8", "--font-size: applies to a figure of a printed size; give --figure-width"},
      {"--dpi 300", "--dpi: applies to a figure of a printed size; give --figure-width"},
  };
  for (const auto& [args, message] : refused) {
    SCOPED_TRACE(args);
    expect_bad_input(
        run_epviz("diagram --case kovalevskaya --area 0.5 --samples 100 --format pdf " + args +
                      " --out " + (d / "diagram").string(),
                  d),
        message);
    EXPECT_FALSE(fs::exists(d / "diagram"));
    const auto bench =
        run_epviz("bench --quick --format pdf " + args + " --out " + (d / "bench").string(), d);
    expect_bad_input(bench, message);
    EXPECT_EQ(bench.err.find("work-precision"), std::string::npos) << "a study ran";
    EXPECT_FALSE(fs::exists(d / "bench"));
    const auto file = d.write("s.section.json", section_file(d, ""));
    expect_bad_input(run_epviz("section " + file.string() + " " + args, d), message);
    EXPECT_FALSE(fs::exists(d / "s.csv"));
    expect_bad_input(run_epviz("merge " + d.path().string() + " " + args, d), message);
  }
}

// The section file's keys are checked as the options are, named by file and key.
TEST(PrintSizeFigures, BadSectionKeysAreNamedByFileAndKey) {
  TempDir d;
  const std::vector<std::pair<std::string, std::string>> refused{
      {R"(, "figure_width": "85")", "key 'figure_width': expected a length such as 85mm"},
      {R"(, "figure_width": 85)", "key 'figure_width': expected a string"},
      {R"(, "figure_width": "85mm", "font_size": 30)", "key 'font_size': '30' is outside"},
      {R"(, "figure_width": "85mm", "dpi": "300")", "key 'dpi': expected a number"},
      {R"(, "font_size": 8)", "key 'font_size': applies to a figure of a printed size"},
  };
  for (const auto& [extra, message] : refused) {
    SCOPED_TRACE(extra);
    const auto file = d.write("s.section.json", section_file(d, extra));
    expect_bad_input(run_epviz("section " + file.string(), d), "s.section.json: " + message);
    EXPECT_FALSE(fs::exists(d / "s.csv"));
  }
}

}  // namespace
}  // namespace epviz::test
