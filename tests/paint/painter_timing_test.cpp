// Not tests: the painter's render-only cost at 1280x720, whole frames and each
// layer alone, on a synthetic frame (no simulation). Run with
//   LP_NUM_THREADS=2 ./test_paint --gtest_also_run_disabled_tests --gtest_filter='*PainterTiming*'
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "paint/frame_painter.hpp"
#include "render/mesh_data.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;

// A frame with a long trail on a nutating cone and its stereographic path.
scene::Frame synthetic_frame(int points) {
  scene::Frame f;
  f.t = 7.5;
  f.view = scene::View::space;
  f.body_rotation = Eigen::Quaternionf(Eigen::AngleAxisf(0.6f, Eigen::Vector3f(1, 0.3f, 0).normalized()));
  f.body.half_extents = {0.30f, 0.42f, 0.18f};
  f.body.centre_of_mass = {0.0f, 0.0f, 0.25f};
  const float pi = std::numbers::pi_v<float>;
  for (int i = 0; i < points; ++i) {
    const float s = float(i) / float(points - 1);  // 0 oldest .. 1 newest
    const float polar = (60.0f + 25.0f * std::sin(9.0f * 2.0f * pi * s)) * pi / 180.0f;
    const float azimuth = 2.3f * 2.0f * pi * s;
    const Eigen::Vector3f p(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
    f.trail.push_back({p, 1.0f - s});
    f.plane_path.push_back({Eigen::Vector2f(p.x() / (1 + p.z()), p.y() / (1 + p.z())), 1.0f - s, false});
  }
  f.current = f.trail.back().p;
  f.plane_current = f.plane_path.back().ab;
  f.trail_label = "body axis 3 (space frame)";
  f.overlay.title = "Kovalevskaya top";
  f.overlay.lines = {"t = 7.500 / 12", "dop853, tol 1e-10", "A = B = 2C, r = (1, 0, 0)"};
  f.overlay.drifts = {{"|gamma|^2", 3e-14}, {"C1 (energy)", 2.1e-12}, {"K", 4e-11}};
  return f;
}

double frames_per_second(paint::FramePainter& painter, const scene::Frame& f, int frames = 40) {
  painter.paint(f);  // warm-up
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < frames; ++i) painter.paint(f);
  return frames / std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(DISABLED_PainterTiming, LayersAt1280x720) {
  et::shared_gl_context();
  for (int samples : {0, 4}) {
    paint::FramePainter painter(et::shared_gl_context(), 1280, 720, {.msaa_samples = samples});
    const scene::Frame all = synthetic_frame(1500);
    std::printf("MSAA %d, all layers: %.1f frames/s\n", samples, frames_per_second(painter, all));
    const char* names[] = {"none", "body", "sphere", "riccati", "overlay"};
    for (int k = 0; k < 5; ++k) {
      scene::Frame f = all;
      f.layers = {k == 1, k == 2, k == 3, k == 4};
      std::printf("  %-8s alone: %.1f frames/s\n", names[k], frames_per_second(painter, f));
    }
  }
}

}  // namespace
}  // namespace epviz

namespace epviz {
namespace {
// The sphere layer's parts drawn alone with the toolkit, to find its costs.
TEST(DISABLED_PainterTiming, SpherePartsAt1280x720) {
  render::RendererOptions o;
  o.width = 1280;
  o.height = 720;
  o.msaa_samples = 0;
  o.overlay = false;
  render::Renderer r(et::shared_gl_context(), o);
  const render::Viewport view{0, 0, 768, 720};
  const auto camera = render::Camera::orbit(glm::vec3(0), 4.7f, 35, 22, 30, view.aspect());
  const scene::Frame f = synthetic_frame(1500);
  auto time = [&](const char* name, auto&& fill) {
    render::DrawList list;
    fill(list);
    auto once = [&] {
      r.begin_frame({0.06f, 0.07f, 0.09f, 1});
      r.draw_3d(list, camera, view);
      r.finish_frame();
    };
    once();
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 40; ++i) once();
    const double ms = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 40;
    std::printf("  %-28s %.2f ms\n", name, ms);
  };
  for (int slices : {24, 48, 72}) {
    render::GpuMesh glass(render::make_uv_sphere(1.0f, slices, slices / 2));
    std::string name = "glass " + std::to_string(slices) + " one pass";
    time(name.c_str(), [&](render::DrawList& l) { l.add_mesh(glass, glm::mat4(1), {{0.55f, 0.7f, 0.95f, 0.16f}, 0.0f, 60, 1.4f, false}); });
    name = "glass " + std::to_string(slices) + " two passes";
    time(name.c_str(), [&](render::DrawList& l) { l.add_mesh(glass, glm::mat4(1), {{0.55f, 0.7f, 0.95f, 0.16f}, 0.0f, 60, 1.4f, true}); });
  }
  {
    render::GpuMesh glass(render::make_uv_sphere(1.0f, 48, 24));
    time("opaque lit sphere 48", [&](render::DrawList& l) { l.add_mesh(glass, glm::mat4(1), {{0.55f, 0.7f, 0.95f, 1.0f}, 0.0f, 60, 0.0f, false}); });
  }
  time("unlit translucent disc", [&](render::DrawList& l) {
    // The sphere's silhouette as a fan facing the camera, through the centre.
    const glm::vec3 eye = camera.eye_position();
    const glm::vec3 n = glm::normalize(eye), u = glm::normalize(glm::cross(n, glm::vec3(0, 0, 1))), v = glm::cross(n, u);
    std::vector<render::ColouredVertex> fan;
    for (int i = 0; i < 96; ++i) {
      const float a0 = 2 * std::numbers::pi_v<float> * float(i) / 96, a1 = 2 * std::numbers::pi_v<float> * float(i + 1) / 96;
      fan.push_back({glm::vec3(0), {0.55f, 0.7f, 0.95f, 0.1f}});
      fan.push_back({std::cos(a0) * u + std::sin(a0) * v, {0.55f, 0.7f, 0.95f, 0.4f}});
      fan.push_back({std::cos(a1) * u + std::sin(a1) * v, {0.55f, 0.7f, 0.95f, 0.4f}});
    }
    l.add_triangles(fan);
  });
  time("nothing (clear + readback)", [](render::DrawList&) {});
  for (int per_circle : {32, 64}) {
    const auto grid = render::make_lat_long_grid(1.0f, 5, 12, per_circle);
    std::string name = "grid " + std::to_string(per_circle) + "/circle";
    time(name.c_str(), [&](render::DrawList& l) { for (const auto& g : grid) l.add_polyline(g, {0.75f, 0.82f, 0.95f, 0.16f}, 2.0f); });
  }
  for (int n : {300, 1500}) {
    std::string name = "trail " + std::to_string(n) + " points";
    time(name.c_str(), [&](render::DrawList& l) {
      std::vector<render::LineVertex> v;
      for (int i = 0; i < n; ++i) {
        const auto& p = f.trail[std::size_t(i * 1499 / (n - 1))].p;
        v.push_back({{p.x(), p.y(), p.z()}, {1, 0.8f, 0.3f, 1}});
      }
      l.add_polyline(v, 4.4f);
    });
  }
}
}  // namespace
}  // namespace epviz
