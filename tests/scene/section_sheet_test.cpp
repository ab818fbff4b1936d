// A section panel shows one sheet of its chart: gamma3 = 0 plotted at
// (gamma1, Omega3) is covered twice (gamma2 > 0 and gamma2 < 0), so the
// panel draws the crossings of the sheet asked and counts the others, and
// its title and note say which sheet and how many were left out.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "scene/section_panel.hpp"

namespace epviz {
namespace {

using scene::SectionSheet;
using sim::StateComponent;

// A crossing of gamma3 = 0 at gamma = (cos a, sin a, 0): on the sheet
// gamma2 > 0 for a in (0, pi), gamma2 < 0 for a in (pi, 2 pi).
sim::Crossing crossing_at(double t, double a, double omega3) {
  sim::Crossing c;
  c.t = t;
  c.gamma = {std::cos(a), std::sin(a), 0.0};
  c.omega = {0.1, -0.2, omega3};
  return c;
}

// Crossings going round the circle, both sheets and the fold (a = 0, pi).
std::vector<sim::Crossing> round_the_circle() {
  std::vector<sim::Crossing> all;
  for (int k = 0; k < 24; ++k) all.push_back(crossing_at(k, 0.3 + 0.61 * k, 0.05 * k - 0.4));
  all.push_back(crossing_at(24, 0.0, 0.5));  // on the fold: both sheets' point
  return all;
}

// The oracle: does the panel's dot list hold exactly the crossings whose
// gamma2, from each crossing's own state, has the sign asked (0 too)?
void expect_only_the_sheet(const scene::SectionPanel& p, const std::vector<sim::Crossing>& all,
                           int sign) {
  std::vector<Eigen::Vector2d> shown;
  std::size_t other = 0;
  for (const auto& c : all) {
    if (sign * c.gamma.y() >= 0.0)
      shown.emplace_back(c.gamma.x(), c.omega.z());
    else
      ++other;
  }
  ASSERT_EQ(p.runs.size(), 1u);
  ASSERT_EQ(p.runs[0].size(), shown.size());
  for (std::size_t k = 0; k < shown.size(); ++k) EXPECT_EQ(p.runs[0][k], shown[k]) << k;
  EXPECT_EQ(p.hidden, other);
  ASSERT_GT(other, 5u) << "the test's crossings lie on both sheets";
}

TEST(SectionSheet, TheDefaultIsThePositiveSheetOfAChartWithTwo) {
  scene::SectionPanelSettings s;  // gamma3 = 0 at (gamma1, Omega3)
  EXPECT_EQ(s.sheet, (SectionSheet{StateComponent::gamma2, 1}));
  EXPECT_EQ(scene::default_sheet(s.surface, s.coords), s.sheet);
  // A chart with one sheet: a surface of Omega3 plotted at (gamma1, gamma2).
  sim::SectionSurface omega3;
  omega3.function = StateComponent::omega3;
  EXPECT_FALSE(
      scene::default_sheet(omega3, {StateComponent::gamma1, StateComponent::gamma2}).has_value());
}

TEST(SectionSheet, EachSheetDrawsItsCrossingsAndCountsTheOthers) {
  const auto all = round_the_circle();
  for (int sign : {1, -1}) {
    SCOPED_TRACE(sign);
    scene::SectionPanelSettings s;
    s.sheet = SectionSheet{StateComponent::gamma2, sign};
    const scene::SectionCrossings crossings(s, {all});
    const auto p = crossings.panel_at(100.0, {scene::Rgba{1, 1, 1, 1}});
    expect_only_the_sheet(p, all, sign);
    EXPECT_EQ(p.title, sign > 0 ? "γ₃ = 0, upward, γ₂ > 0" : "γ₃ = 0, upward, γ₂ < 0");
    EXPECT_EQ(p.note, std::to_string(p.hidden) + " crossings on " +
                          (sign > 0 ? "γ₂ < 0" : "γ₂ > 0") + " not drawn");
    // The axes fit the dots drawn (every one inside).
    for (const auto& d : p.runs[0])
      EXPECT_TRUE(d.x() > p.range[0] && d.x() < p.range[1] && d.y() > p.range[2] &&
                  d.y() < p.range[3]);
  }
}

TEST(SectionSheet, OnlyCrossingsUpToTheTimeAreCounted) {
  const auto all = round_the_circle();
  scene::SectionPanelSettings s;
  const scene::SectionCrossings crossings(s, {all});
  const double t = 9.5;
  std::vector<sim::Crossing> early;
  for (const auto& c : all)
    if (c.t <= t) early.push_back(c);
  const auto p = crossings.panel_at(t, {scene::Rgba{1, 1, 1, 1}});
  std::size_t other = 0;
  for (const auto& c : early) other += c.gamma.y() < 0.0 ? 1 : 0;
  EXPECT_EQ(p.hidden, other);
  EXPECT_EQ(p.runs[0].size(), early.size() - other);
}

TEST(SectionSheet, WithoutASheetEveryCrossingIsDrawnAndNothingIsSaid) {
  const auto all = round_the_circle();
  scene::SectionPanelSettings s;
  s.sheet.reset();
  const auto p = scene::SectionCrossings(s, {all}).panel_at(100.0, {scene::Rgba{1, 1, 1, 1}});
  EXPECT_EQ(p.runs[0].size(), all.size());
  EXPECT_EQ(p.hidden, 0u);
  EXPECT_TRUE(p.note.empty());
  EXPECT_EQ(p.title, "γ₃ = 0, upward");
}

}  // namespace
}  // namespace epviz
