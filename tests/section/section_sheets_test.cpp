// Sections drawn as charts: a picture never lays two sheets of its surface
// on one plane without saying so, and the shipped sections draw each sheet
// apart, so that crossings close in the plot are close in state.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/bad_input.hpp"
#include "section/section_chart.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"
#include "section/sheet_fold.hpp"

namespace epviz::section {
namespace {

// Points of the unit circle plotted by x alone (y is a second, shared
// coordinate): the upper and the lower half meet only at x = +-1.
std::vector<PlottedCrossing> circle(int n, bool both_halves) {
  std::vector<PlottedCrossing> out;
  for (int i = 0; i < n; ++i) {
    const double x = -0.9 + 1.8 * (i + 0.5) / n;
    const double y = std::fmod(i * 0.618034, 1.0);
    for (const double sign : {1.0, -1.0}) {
      if (sign < 0 && !both_halves) continue;
      out.push_back({x, y, {0, 0, y, x, sign * std::sqrt(1 - x * x), 0}});
    }
  }
  return out;
}

TEST(SheetFolds, TwoSheetsOnOnePlaneAreMeasuredOneSheetIsNot) {
  const FoldMeasure one = measure_folds(circle(4000, false));
  const FoldMeasure two = measure_folds(circle(4000, true));
  EXPECT_EQ(one.far_pairs, 0) << one.close_pairs << " close pairs";
  EXPECT_GT(two.far_pairs, 3000) << two.close_pairs << " close pairs";
}

TEST(SheetFolds, NeighboursAlongOneSheetAreCloseInState) {
  // Dense along one curve: many close pairs, none far apart.
  std::vector<PlottedCrossing> line;
  for (int i = 0; i < 20000; ++i) {
    const double s = i / 20000.0;
    line.push_back({s, s * s, {s, 0, 0, 1 - s, 0, 0}});
  }
  const FoldMeasure m = measure_folds(line);
  EXPECT_GT(m.close_pairs, 10000);
  EXPECT_EQ(m.far_pairs, 0);
}

SectionJob shipped(const std::string& name) {
  return read_section_job(std::filesystem::path(EPVIZ_SOURCE_DIR) / "render_jobs" /
                          (name + ".section.json"));
}

// Every shipped section draws charts: with its sheets as shipped, no panel
// folds; with the sheets taken away (every crossing on one plane), the same
// crossings do fold, so that the measure can fail.
class ShippedSections : public ::testing::TestWithParam<const char*> {};

TEST_P(ShippedSections, EveryPanelIsAChart) {
  SectionJob job = shipped(GetParam());
  ASSERT_TRUE(job.sheet.has_value()) << GetParam() << " ships without a sheet";
  job.crossings = std::min(job.crossings, 150);  // enough crossings to fold, in a few seconds
  const auto orbits = run_section(job, section_starts(job), 2);
  const auto warnings = fold_warnings(job, orbits);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  for (const auto& c : section_charts(job, orbits))
    EXPECT_EQ(c.title.find("folded"), std::string::npos) << c.title;
  job.sheet.reset();
  EXPECT_FALSE(fold_warnings(job, orbits).empty())
      << GetParam() << ": one plane for both sheets and no fold found";
}

INSTANTIATE_TEST_SUITE_P(Sections, ShippedSections,
                         ::testing::Values("generic", "kovalevskaya", "kovalevskaya_methods"));

TEST(SectionSheets, SheetsSplitEachMethodIntoTwoPanelsOneSheetEach) {
  SectionJob job = shipped("kovalevskaya");
  job.crossings = 40;
  job.orbits = 4;
  const auto orbits = run_section(job, section_starts(job), 2);
  job.sheet = SheetChoice{sim::StateComponent::gamma2, SheetChoice::Show::both_apart};
  const auto charts = section_charts(job, orbits);
  ASSERT_EQ(charts.size(), 2u);
  EXPECT_NE(charts[0].title.find("γ₂ > 0"), std::string::npos) << charts[0].title;
  EXPECT_NE(charts[1].title.find("γ₂ < 0"), std::string::npos) << charts[1].title;
  // Every crossing off the fold is drawn in exactly one panel.
  std::size_t drawn = 0, crossings = 0;
  for (const auto& c : charts)
    for (const auto& s : c.series) drawn += s.points.size();
  for (const auto& o : orbits)
    if (!o.failure) crossings += o.crossings.size();
  EXPECT_EQ(drawn, crossings);
  job.sheet->show = SheetChoice::Show::negative;
  const auto negative = section_charts(job, orbits);
  ASSERT_EQ(negative.size(), 1u);
  std::size_t below = 0;
  for (const auto& o : orbits)
    for (const auto& c : o.crossings) below += c.gamma.y() < 0;
  std::size_t drawn_below = 0;
  for (const auto& s : negative[0].series) drawn_below += s.points.size();
  EXPECT_EQ(drawn_below, below);
}

TEST(SectionSheets, ASheetMustBeAFreeComponentWithASide) {
  const auto dir = std::filesystem::path(EPVIZ_SOURCE_DIR) / "render_jobs";
  nlohmann::json doc = io::read_json_file(dir / "kovalevskaya.section.json");
  doc.erase("sheets");
  const auto refused = [&](const char* key, const char* value, const char* says) {
    nlohmann::json d = doc;
    d[key] = value;
    try {
      read_section_object(d, "k.section.json");
      ADD_FAILURE() << key << " = " << value << " accepted";
    } catch (const io::BadInput& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  refused("sheet", "gamma3 > 0", "one of omega1, omega2, gamma2");  // the surface's own
  refused("sheet", "gamma1 > 0", "key 'sheet'");                    // plotted
  refused("sheet", "gamma2 >= 0", "\"C > 0\" or \"C < 0\"");
  refused("sheet", "gamma2\n> 0", "\\n");  // quoted on one line
  refused("sheets", "omega9", "key 'sheets'");
  nlohmann::json both = doc;
  both["sheet"] = "gamma2 > 0";
  both["sheets"] = "gamma2";
  EXPECT_THROW(read_section_object(both, "k.section.json"), io::BadInput);
  nlohmann::json good = doc;
  good["sheet"] = "omega1 < 0";
  const SectionJob job = read_section_object(good, "k.section.json");
  ASSERT_TRUE(job.sheet);
  EXPECT_EQ(job.sheet->component, sim::StateComponent::omega1);
  EXPECT_EQ(job.sheet->show, SheetChoice::Show::negative);
}

}  // namespace
}  // namespace epviz::section
