// A render's still at a printed size (`epviz render JOB --figure-width 85mm`):
// the page as wide as asked, every word of it (the overlay's, the legend's,
// the panels' and the keys') at least 6 pt tall and none over another, read
// back by poppler, for a single run, a comparison and a scene with a section
// panel; PNG frames that many inches at the dpi; and what cannot go together
// refused before any work.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/png_reader.hpp"
#include "support/cli.hpp"
#include "support/pdf_words.hpp"

namespace epviz::test {
namespace {

namespace fs = std::filesystem;

constexpr double kColumnPt = 85.0 / 25.4 * 72.0;  // 240.94 pt
constexpr double kLeastWordPt = 6.0;

fs::path only_file(const fs::path& dir, const std::string& extension) {
  fs::path found;
  int count = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == extension) found = e.path(), ++count;
  EXPECT_EQ(count, 1) << dir;
  return found;
}

TEST(PrintSizeFrames, EachKindOfSceneIsAColumnWideWithPrintableText) {
  if (!have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
  TempDir d;
  // What each scene must show in words: its overlay, a comparison's legend,
  // the section panel's title.
  const std::pair<std::string, std::string> scenes[] = {{"kovalevskaya", "drift"},
                                                        {"compare_methods", "midpoint"},
                                                        {"kovalevskaya_section_panel", "section"}};
  for (const auto& [job, word] : scenes) {
    SCOPED_TRACE(job);
    const auto out = d / job;
    const auto r = run_epviz(
        "render " + job + " --format pdf --figure-width 85mm --quiet --out " + out.string(), d);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto pdf = only_file(out, ".pdf");
    EXPECT_NEAR(pdf_page_width_pt(pdf), kColumnPt, 0.5);
    const auto [w, h] = pdf_page_size_pt(pdf);
    EXPECT_GT(h, w) << "a column's figure is taller than wide";
    const auto words = pdf_words(pdf);
    ASSERT_GT(words.size(), 40u);
    bool shown = false;
    for (const auto& wd : words) {
      EXPECT_GE(wd.height(), kLeastWordPt) << "'" << wd.text << "'";
      // 8 pt asked: the text is that size, not smaller, not larger.
      EXPECT_LE(wd.height(), 9.0) << "'" << wd.text << "'";
      EXPECT_GE(wd.x0, -0.01) << "'" << wd.text << "' leaves the page";
      EXPECT_LE(wd.x1, w + 0.01) << "'" << wd.text << "' leaves the page";
      shown = shown || wd.text.find(word) != std::string::npos;
    }
    EXPECT_TRUE(shown) << "no word '" << word << "'";
    for (const auto& [a, b] : overlapping_words(words))
      ADD_FAILURE() << "'" << a.text << "' (" << a.x0 << ", " << a.y0 << ") overlaps '" << b.text
                    << "' (" << b.x0 << ", " << b.y0 << ")";
  }
}

// A larger font makes the page taller, not the text smaller: 10 pt words
// on the same width.
TEST(PrintSizeFrames, TheFontAskedIsTheFontPrinted) {
  if (!have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
  TempDir d;
  double height_at[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    const std::string font = i == 0 ? "8" : "10";
    const auto out = d / font;
    const auto r = run_epviz("render kovalevskaya --format pdf --figure-width 3.5in --font-size " +
                                 font + " --quiet --out " + out.string(),
                             d);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto pdf = only_file(out, ".pdf");
    EXPECT_NEAR(pdf_page_width_pt(pdf), 252.0, 0.5);
    height_at[i] = pdf_page_size_pt(pdf).second;
    double tallest = 0.0;
    for (const auto& wd : pdf_words(pdf)) tallest = std::max(tallest, wd.height());
    EXPECT_NEAR(tallest, std::stod(font), 0.3);
  }
  EXPECT_GT(height_at[1], height_at[0]);
}

TEST(PrintSizeFrames, PngFramesAreThatManyInchesAtTheDpi) {
  TempDir d;
  const auto r = run_epviz(
      "render lagrange --frames 0 --format png --figure-width 3.5in --dpi 150 --quiet --out " +
          (d / "png").string(),
      d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto size = io::read_png_size(only_file(d / "png", ".png"));
  ASSERT_TRUE(size);
  EXPECT_EQ(size->width, 525);  // 3.5 in at 150 dpi
  EXPECT_GT(size->height, size->width);
}

TEST(PrintSizeFrames, WhatCannotGoTogetherIsRefusedBeforeAnyWork) {
  TempDir d;
  const std::pair<std::string, std::string> refused[] = {
      {"kovalevskaya --figure-width 85mm --width 640",
       "--width: a figure of a printed size (--figure-width) takes its pixels from --dpi"},
      {"kovalevskaya --figure-width 85mm --height 640", "--height: a figure of a printed size"},
      {"gallery --figure-width 85mm", "--figure-width: a gallery's tiles are screen pictures"},
      {"kovalevskaya --figure-width 85", "--figure-width: expected a length such as 85mm"},
      {"kovalevskaya --font-size 9", "--font-size: applies to a figure of a printed size"},
      {"kovalevskaya --figure-width 10in --dpi 1200",
       "--figure-width: at --dpi 1200 the figure would be 12000 x"},
  };
  for (const auto& [args, message] : refused) {
    SCOPED_TRACE(args);
    expect_bad_input(run_epviz("render " + args + " --format pdf --out " + (d / "o").string(), d),
                     message);
    EXPECT_FALSE(fs::exists(d / "o"));
  }
}

// A job file's "output" keys ask for the same, and the options go over them.
TEST(PrintSizeFrames, AJobsOutputKeysAskForTheSameAndTheOptionsWin) {
  if (!have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
  TempDir d;
  const auto job = d.write("j.json", R"({"simulation": {"case": "lagrange", "t_end": 5},
    "output": {"figure_width": "3.5in", "font_size": 9}})");
  auto r = run_epviz(
      "render " + job.string() + " --format pdf --quiet --out " + (d / "file").string(), d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto pdf = only_file(d / "file", ".pdf");
  EXPECT_NEAR(pdf_page_width_pt(pdf), 252.0, 0.5);
  double tallest = 0.0;
  for (const auto& wd : pdf_words(pdf)) tallest = std::max(tallest, wd.height());
  EXPECT_NEAR(tallest, 9.0, 0.3);
  r = run_epviz("render " + job.string() + " --figure-width 85mm --format pdf --quiet --out " +
                    (d / "option").string(),
                d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(pdf_page_width_pt(only_file(d / "option", ".pdf")), kColumnPt, 0.5);
}

TEST(PrintSizeFrames, AJobsBadOrLoneKeysAreNamedByFileAndKey) {
  TempDir d;
  const std::pair<std::string, std::string> refused[] = {
      {R"("figure_width": "85")", "output.figure_width': expected a length such as 85mm"},
      {R"("figure_width": "85mm", "font_size": 40)", "output.font_size"},
      {R"("font_size": 9)", "output.font_size: applies to a figure of a printed size"},
      {R"("dpi": 150)", "output.dpi: applies to a figure of a printed size"},
  };
  for (const auto& [keys, message] : refused) {
    SCOPED_TRACE(keys);
    const auto job = d.write("j.json", R"({"simulation": {"case": "lagrange", "t_end": 5},
      "output": {)" + keys + "}}");
    expect_bad_input(
        run_epviz("render " + job.string() + " --format pdf --out " + (d / "o").string(), d),
        message);
    EXPECT_FALSE(fs::exists(d / "o"));
  }
}

}  // namespace
}  // namespace epviz::test
