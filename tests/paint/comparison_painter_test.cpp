// Comparison scenes in pixels: a run identical to the first draws exactly on
// the first's trail (its stripe inside the first's line), a run that differs
// draws elsewhere.
#include <gtest/gtest.h>

#include <cstdlib>

#include "paint/frame_painter.hpp"
#include "physics/cases.hpp"
#include "render/render_test_support.hpp"
#include "scene/frame_source.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
constexpr int W = 480, H = 270;

paint::FramePainter& painter() {
  static paint::FramePainter p(et::shared_gl_context(), W, H, {.builtin_font = true});
  return p;
}

// The last frame of a two-run Kovalevskaya scene: DOP853, then `second`.
scene::Frame two_runs(const sim::RunSpec& second) {
  const auto first = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                                     sim::Formulation::direct, 12.0, 1);
  scene::SceneSettings s;
  s.width = W, s.height = H, s.fps = 10, s.duration = 2;
  s.layers = scene::Layers::only(
      {scene::Layer::sphere, scene::Layer::riccati});  // sphere and plane: the trails alone
  scene::FrameSource src(
      scene::plan_scene({{first, "a", false, true}, {second, "b", false, true}}, s), s);
  return src.frame(src.frame_count() - 1);
}

using Mask = std::vector<bool>;
Mask differs(const render::RgbaImage& a, const render::RgbaImage& b) {
  Mask m(std::size_t(W) * H, false);
  for (std::size_t i = 0; i < m.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(a.pixels[4 * i + c]) - int(b.pixels[4 * i + c])) > 2) m[i] = true;
  return m;
}
Mask dilated(const Mask& m) {
  Mask d = m;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (m[std::size_t(y) * W + x])
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u >= 0 && v >= 0 && u < W && v < H) d[std::size_t(v) * W + u] = true;
          }
  return d;
}

struct Counts {
  long second = 0;   // pixels the second run's trails change
  long outside = 0;  // of those, outside the first run's line
};
Counts second_run_pixels(const scene::Frame& f) {
  // The second run's trails removed (its ghost markers kept): what they draw.
  scene::Frame without = f;
  without.comparison->others[0].trail.clear();
  without.comparison->others[0].plane_path.clear();
  // The first run's trails removed too: where the first run's line lies.
  scene::Frame bare = without;
  bare.trail = {bare.trail.back()};
  bare.plane_path.clear();
  const auto with_img = painter().paint(f);
  const auto without_img = painter().paint(without);
  const auto bare_img = painter().paint(bare);
  const Mask second = differs(with_img, without_img);
  const Mask first = dilated(differs(without_img, bare_img));
  Counts c;
  for (std::size_t i = 0; i < second.size(); ++i)
    if (second[i]) ++c.second, c.outside += !first[i];
  return c;
}

TEST(ComparisonPainter, AnIdenticalRunDrawsOnTheFirstRunsLine) {
  const auto same = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                                    sim::Formulation::direct, 12.0, 1);
  const auto c = second_run_pixels(two_runs(same));
  EXPECT_GT(c.second, 200) << "the second run's stripe is drawn";
  EXPECT_EQ(c.outside, 0);
}

TEST(ComparisonPainter, ADifferentRunDrawsElsewhere) {
  auto coarse = sim::preset_run(physics::Case::kovalevskaya, sim::Method::rk4,
                                sim::Formulation::direct, 12.0, 1);
  coarse.step = 0.6;
  const auto c = second_run_pixels(two_runs(coarse));
  EXPECT_GT(c.outside, 200) << "of " << c.second;
}

}  // namespace
}  // namespace epviz
