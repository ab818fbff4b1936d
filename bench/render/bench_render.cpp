// The costs behind the README's 1280x720 frames/s figures, on the Kovalevskaya
// job's frames (prebuilt, so that only the measured stage is timed): painting
// (GL to pixels), PNG encoding per zlib level and row filter, and MP4 encoding
// through the ffmpeg pipe. Painting is measured on each GL backend (EGL and
// OSMesa); the encoders use the EPVIZ_GL backend's frame. The cloud's cost:
// the frames of the shipped render_jobs/cloud_generic.json (10,000 members)
// painted with and without their cloud, and those frames through the MP4 pipe.
//
//   LP_NUM_THREADS=2 build/bench/epviz_render_bench
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "io/png_writer.hpp"
#include "io/video_writer.hpp"
#include "job/job_file.hpp"
#include "job/job_plan.hpp"
#include "paint/frame_painter.hpp"
#include "physics/cases.hpp"
#include "scene/frame_source.hpp"

namespace {

using namespace epviz;

std::vector<scene::Frame> frames(int width, int height, int count) {
  const auto run = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                                   sim::Formulation::direct, 40, 200);
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

// Frames spread over the shipped cloud job, with its cloud or without it.
std::vector<scene::Frame> cloud_job_frames(bool with_cloud, int count) {
  const auto loaded = job::load_job_file(EPVIZ_SOURCE_DIR "/render_jobs/cloud_generic.json");
  auto job = *loaded.single;
  if (!with_cloud) job.scene.cloud = {};
  scene::FrameSource source(job::plan_job(job), job.scene);
  std::vector<scene::Frame> out;
  for (int i = 0; i < count; ++i) out.push_back(source.frame(i * source.frame_count() / count));
  return out;
}

// One context per backend name, made on first use.
render::GlContext& context(const std::string& backend = render::gl_backend_from_environment()) {
  static std::map<std::string, std::unique_ptr<render::GlContext>> contexts;
  auto& c = contexts[backend];
  if (!c) c = render::make_gl_context(backend, 64, 64);
  c->make_current();
  return *c;
}

// Paints `fs` in turn at 1280x720, one a benchmark iteration.
void paint_in_turn(benchmark::State& state, const std::vector<scene::Frame>& fs,
                   render::GlContext& gl, paint::PainterOptions options = {}) {
  state.SetLabel(gl.describe());
  paint::FramePainter painter(gl, 1280, 720, options);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& img = painter.paint(fs[i++ % fs.size()]);
    benchmark::DoNotOptimize(img.pixels.data());
  }
  state.counters["frames/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

void paint_frames(benchmark::State& state, const std::string& backend) {
  static const auto fs = frames(1280, 720, 64);
  paint_in_turn(state, fs, context(backend), {.msaa_samples = int(state.range(0))});
}

// The cloud job's frames painted (drawn and read back, nothing encoded).
void paint_cloud_frames(benchmark::State& state) {
  static const auto clouded = cloud_job_frames(true, 48);
  static const auto bare = cloud_job_frames(false, 48);
  paint_in_turn(state, state.range(0) != 0 ? clouded : bare, context());
}

// One rendered frame, for the encoders.
const render::RgbaImage& sample_image() {
  static const render::RgbaImage image = [] {
    const auto fs = frames(1280, 720, 2);
    paint::FramePainter painter(context(), 1280, 720);
    return painter.paint(fs[1]);
  }();
  return image;
}

void png_encode(benchmark::State& state) {
  const auto& img = sample_image();
  const io::PngOptions opts{int(state.range(0)), int(state.range(1))};
  std::size_t bytes = 0;
  for (auto _ : state) bytes = io::encode_png_rgba(img.width, img.height, img.pixels, opts).size();
  state.counters["kB"] = double(bytes) / 1024.0;
}

void mp4_encode(benchmark::State& state) {
  const auto& img = sample_image();
  const auto path = std::filesystem::temp_directory_path() / "epviz_bench.mp4";
  io::VideoWriter video(path, io::VideoFormat::mp4, img.width, img.height, 30.0);
  for (auto _ : state) video.write_frame(img.pixels.data());
  video.finish();
  std::filesystem::remove(path);
  state.counters["frames/s"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(png_encode)
    ->Name("png_encode_1280x720/level_filter")
    ->ArgsProduct({{1, 4, 6}, {0, -1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(mp4_encode)
    ->Name("mp4_encode_1280x720")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

BENCHMARK(paint_cloud_frames)
    ->Name("render_only_cloud_job")
    ->ArgName("with_cloud")
    ->Arg(1)
    ->Arg(0)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(paint_frames, egl, std::string("egl"))
    ->Name("render_only_1280x720_egl/msaa")
    ->Arg(0)
    ->Arg(4)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(paint_frames, osmesa, std::string("osmesa"))
    ->Name("render_only_1280x720_osmesa/msaa")
    ->Arg(0)
    ->Arg(4)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
