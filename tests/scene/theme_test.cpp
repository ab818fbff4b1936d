// The themes: the drift traffic light's levels, names, and text that reads on
// each theme's background (WCAG contrast ratio, computed here from sRGB).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene/theme.hpp"

namespace epviz {
namespace {

double linear(float c) { return c <= 0.04045f ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double luminance(const scene::Rgba& c) {
  return 0.2126 * linear(c[0]) + 0.7152 * linear(c[1]) + 0.0722 * linear(c[2]);
}
double contrast(const scene::Rgba& a, const scene::Rgba& b) {
  const double la = luminance(a), lb = luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

TEST(DriftLevel, GreenNearRoundOffAmberBelowAPercentRedFromThere) {
  EXPECT_EQ(scene::drift_level(0.0), scene::DriftLevel::ok);
  EXPECT_EQ(scene::drift_level(3e-13), scene::DriftLevel::ok);
  EXPECT_EQ(scene::drift_level(1e-8), scene::DriftLevel::warn);
  EXPECT_EQ(scene::drift_level(5e-3), scene::DriftLevel::warn);
  EXPECT_EQ(scene::drift_level(1e-2), scene::DriftLevel::bad);
  EXPECT_EQ(scene::drift_level(std::numeric_limits<double>::quiet_NaN()), scene::DriftLevel::bad);
  EXPECT_EQ(scene::drift_level(std::numeric_limits<double>::infinity()), scene::DriftLevel::bad);
  const auto& t = scene::dark_theme();
  EXPECT_EQ(&t.drift_colour(1e-12), &t.drift_ok);
  EXPECT_EQ(&t.drift_colour(1e-5), &t.drift_warn);
  EXPECT_EQ(&t.drift_colour(0.5), &t.drift_bad);
}

TEST(Theme, NamesRoundTrip) {
  for (auto id : {scene::ThemeId::dark, scene::ThemeId::light})
    EXPECT_EQ(scene::theme_from_name(scene::name(id)), id);
  EXPECT_FALSE(scene::theme_from_name("sepia"));
  EXPECT_EQ(&scene::theme(scene::ThemeId::dark), &scene::dark_theme());
}

TEST(Theme, BackgroundKindMatchesTheTheme) {
  EXPECT_FALSE(scene::is_light(scene::dark_theme().colours.background));
  EXPECT_TRUE(scene::is_light(scene::light_theme().colours.background));
  EXPECT_TRUE(scene::dark_theme().colours.background == scene::Colours{}.background);
}

TEST(Theme, TextReadsOnItsBackground) {
  for (const auto* t : {&scene::dark_theme(), &scene::light_theme()}) {
    const auto& bg = t->colours.background;
    EXPECT_GE(contrast(t->axis_label, bg), 7.0) << t->name;
    EXPECT_GE(contrast(t->pole_label, bg), 7.0) << t->name;
    EXPECT_GE(contrast(t->panel_text, t->panel_background), 7.0) << t->name;
    EXPECT_GE(contrast(t->trail_caption, bg), 4.5) << t->name;
    for (const auto& c : t->axes) EXPECT_GE(contrast(c, bg), 3.0) << t->name;
    EXPECT_GE(contrast(t->infinity_label, t->panel_background), 3.0) << t->name;
  }
}

}  // namespace
}  // namespace epviz
