// The comparison's separation chart as drawn into a list: its y labels are
// the decades of the data's range in print, its time axis has ticks, the
// curves stay inside their range, and every mark and label stays inside the
// rectangle the layout gives it without two labels overlapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "paint/figure_common.hpp"
#include "paint/fixed_width_font.hpp"
#include "paint/separation_chart.hpp"
#include "paint/small_chart_axes.hpp"
#include "scene/theme.hpp"

namespace epviz {
namespace {

// A stand-in for the font: 7 px per character, 13 px tall.
const auto& measure = epviz::testing::fixed_width_measure;

// Two runs beyond the first whose separation grows from `from` to `to`
// (log-evenly) over t in [0, 40].
scene::Comparison comparison(double from, double to) {
  scene::Comparison c;
  c.colours = {{1, 1, 1, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}};
  c.lines = {scene::LineStyle::solid, scene::LineStyle::solid, scene::LineStyle::solid};
  c.t_end = 40.0;
  for (int run = 0; run < 2; ++run) {
    scene::RunTrace r;
    for (int i = 0; i <= 100; ++i) {
      const double f = i / 100.0;
      r.separation.emplace_back(
          float(40.0 * f), float(std::pow(10.0, std::log10(from) * (1 - f) + std::log10(to) * f) *
                                 (run == 0 ? 1.0 : 2.0)));
    }
    c.others.push_back(r);
  }
  return c;
}

std::vector<render::TextLabel> labels_of(const render::DrawList& list) { return list.labels(); }

std::set<std::string> texts(const render::DrawList& list) {
  std::set<std::string> s;
  for (const auto& l : list.labels()) s.insert(l.text);
  return s;
}

render::DrawList draw(const scene::Comparison& c, const scene::Rect& area) {
  render::DrawList list;
  paint::draw_separation_chart(list, c, area, scene::dark_theme(), 1.0f, measure);
  return list;
}

TEST(SeparationChart, LabelsEveryDecadeOfTheDataWhenTheyFit) {
  const auto c = comparison(3e-7, 0.5);
  const auto list = draw(c, {0, 0, 420, 220});
  const auto drawn = texts(list);
  // 3·10⁻⁷ lies in the decade from 10⁻⁷: every decade from there to 10⁰.
  for (int e = -7; e <= 0; ++e)
    EXPECT_TRUE(drawn.count(paint::power_of_ten(e))) << "no label " << paint::power_of_ten(e);
  EXPECT_FALSE(drawn.count(paint::power_of_ten(-8)));
  EXPECT_FALSE(drawn.count(paint::power_of_ten(1)));
}

TEST(SeparationChart, TheRangeCoversTheSmallestPositiveValue) {
  auto c = comparison(1e-3, 1.0);
  c.others[1].separation[50].y() = 4e-11f;  // a dip deep under the rest
  c.others[0].separation[0].y() = 0.0f;     // runs that agree exactly
  const auto r = paint::separation_range(c);
  EXPECT_EQ(r.lo, -11);
  EXPECT_GE(r.hi, std::log10(2.0) - 1e-9);
}

TEST(SeparationChart, AtLeastThreeDecadesAndNeverBelowTheFloor) {
  EXPECT_EQ(paint::separation_range(comparison(0.2, 1.0)).lo, -3);
  auto tiny = comparison(1e-3, 1.0);
  tiny.others[0].separation[3].y() = 1e-30f;
  EXPECT_EQ(paint::separation_range(tiny).lo, -16);
}

TEST(SeparationChart, ATimeAxisWithTicksUpToItsEnd) {
  const auto list = draw(comparison(1e-6, 1.0), {0, 0, 420, 160});
  std::vector<double> times;
  for (const auto& l : list.labels())
    if (l.anchor == render::TextAnchor::top) times.push_back(std::stod(l.text));
  ASSERT_GE(times.size(), 3u);
  EXPECT_EQ(times.front(), 0.0);
  EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
  EXPECT_LE(times.back(), 40.0);
  EXPECT_GE(times.back(), 20.0);
}

// Every label and line vertex inside `area`, no two labels overlapping.
void expect_inside_and_apart(const render::DrawList& list, const scene::Rect& area) {
  const auto labels = labels_of(list);
  std::vector<paint::TextBox> boxes;
  for (const auto& l : labels) boxes.push_back(paint::text_box(l, measure(l.text)));
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    EXPECT_GE(boxes[i].min.x, float(area.x) - 0.5f) << labels[i].text;
    EXPECT_GE(boxes[i].min.y, float(area.y) - 0.5f) << labels[i].text;
    EXPECT_LE(boxes[i].max.x, float(area.right()) + 0.5f) << labels[i].text;
    EXPECT_LE(boxes[i].max.y, float(area.bottom()) + 0.5f) << labels[i].text;
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      EXPECT_FALSE(boxes[i].intersects(boxes[j])) << labels[i].text << " / " << labels[j].text;
  }
  for (const auto& v : list.line_vertices()) {
    EXPECT_GE(v.position.x, float(area.x) - 1.0f);
    EXPECT_LE(v.position.x, float(area.right()) + 1.0f);
    EXPECT_GE(v.position.y, float(area.y) - 1.0f);
    EXPECT_LE(v.position.y, float(area.bottom()) + 1.0f);
  }
}

TEST(SeparationChart, StaysInItsRectangleWithoutOverlapsLargeAndSmall) {
  // The chart areas of 1280x720 and 640x360 frames, and a narrow one.
  for (const scene::Rect area :
       {scene::Rect{830, 565, 426, 115}, scene::Rect{415, 283, 213, 57}, {10, 10, 120, 40}}) {
    SCOPED_TRACE(std::to_string(area.width) + "x" + std::to_string(area.height));
    expect_inside_and_apart(draw(comparison(1e-9, 1.5), area), area);
  }
}

// The small arrows down (three vertices, the middle one lowest, 3 px each
// side) in `list`: their tips.
std::vector<glm::vec3> arrow_tips(const render::DrawList& list) {
  std::vector<glm::vec3> tips;
  for (const auto& p : list.polylines()) {
    if (p.count != 3 || p.closed) continue;
    const auto& v = list.line_vertices();
    const glm::vec3 a = v[p.first].position, b = v[p.first + 1].position,
                    c = v[p.first + 2].position;
    if (std::abs(a.y - c.y) < 1e-3f && std::abs(b.y - a.y - 3.0f) < 1e-3f &&
        std::abs(b.x - a.x - 3.0f) < 1e-3f && std::abs(c.x - b.x - 3.0f) < 1e-3f)
      tips.push_back(b);
  }
  return tips;
}

// The plot's frame: the one closed polyline.
float frame_bottom(const render::DrawList& list) {
  for (const auto& p : list.polylines())
    if (p.closed) {
      float y = -1e9f;
      for (std::size_t i = 0; i < p.count; ++i)
        y = std::max(y, list.line_vertices()[p.first + i].position.y);
      return y;
    }
  return 0.0f;
}

TEST(SeparationChart, ValuesUnderTheRangeAreMarkedOnTheBottomEdge) {
  auto c = comparison(1e-4, 1.0);
  EXPECT_TRUE(arrow_tips(draw(c, {0, 0, 420, 160})).empty());
  c.others[0].separation[0].y() = 0.0f;  // identical at t = 0
  const auto with = draw(c, {0, 0, 420, 160});
  const auto tips = arrow_tips(with);
  ASSERT_EQ(tips.size(), 1u);
  EXPECT_NEAR(tips[0].y, frame_bottom(with), 1.0f);
}

TEST(SeparationChart, TheTitleSaysWhatIsPlotted) {
  const auto list = draw(comparison(1e-6, 1.0), {0, 0, 420, 160});
  bool found = false;
  for (const auto& l : list.labels())
    found = found || (l.text.find("|Δγ|") != std::string::npos &&
                      l.text.find("against t") != std::string::npos);
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace epviz
