// Render-only cost of a 1280x720 frame (GL to pixels, no encoding), for the
// README's frames/s figures: the Kovalevskaya job's frames, prebuilt so that
// only painting is timed.
//
//   LP_NUM_THREADS=2 build/bench/epviz_render_bench
#include <benchmark/benchmark.h>

#include "paint/frame_painter.hpp"
#include "physics/cases.hpp"
#include "scene/frame_source.hpp"

namespace {

using namespace epviz;

std::vector<scene::Frame> frames(int width, int height, int count) {
  const auto run = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853, sim::Formulation::direct, 40, 200);
  scene::SceneSettings s;
  s.width = width;
  s.height = height;
  s.trail_length = 20;
  s.duration = 9;
  scene::FrameSource source(scene::plan_scene(run, s), s);
  std::vector<scene::Frame> out;
  for (int i = 0; i < count; ++i) out.push_back(source.frame(i * source.frame_count() / count));
  return out;
}

render::GlContext& context() {
  static auto c = render::make_gl_context(render::gl_backend_from_environment(), 64, 64);
  return *c;
}

void paint_frames(benchmark::State& state) {
  const int w = 1280, h = 720;
  static const auto fs = frames(w, h, 64);
  paint::FramePainter painter(context(), w, h, {.msaa_samples = int(state.range(0))});
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& img = painter.paint(fs[i++ % fs.size()]);
    benchmark::DoNotOptimize(img.pixels.data());
  }
  state.counters["frames/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(paint_frames)->Name("render_only_1280x720/msaa")->Arg(0)->Arg(4)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
