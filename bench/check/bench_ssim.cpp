// The cost of comparing two frames by SSIM (check::SsimWorkspace), the
// comparison alone: the images are in memory before the clock starts.
//
// Without --pairs it compares synthetic 1280x720 pairs made here (a picture
// and the same picture moved by a pixel, with noise). With --pairs DIR it
// compares DIR/<k>_a.png with DIR/<k>_b.png for k = 0, 1, ... until one is
// missing: bench/check/ssim_vs_skimage.py times scikit-image on those same
// files in the same run.
//
//   build/bench/epviz_ssim_bench [--pairs DIR] [Google Benchmark flags]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "check/ssim.hpp"
#include "io/png_reader.hpp"

namespace {

using epviz::io::RgbaPixels;

struct Pair {
  RgbaPixels a, b;
};

std::vector<Pair>& pairs() {
  static std::vector<Pair> all;
  return all;
}

// A frame-like picture: a vertical gradient, a disc and a few thin lines,
// drawn with its disc and lines moved by `shift` pixels.
RgbaPixels picture(int w, int h, int shift) {
  RgbaPixels im{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4, 255)};
  const int cx = w / 2 + shift, cy = h / 2, r = h / 4;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = &im.rgba[(std::size_t(y) * w + x) * 4];
      const bool disc = (x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r;
      const bool line = (x + shift) % 97 == 0 || (x + 2 * y + shift) % 151 == 0;
      p[0] = disc ? 230 : line ? 250 : std::uint8_t(20 + 40 * y / h);
      p[1] = disc ? 120 : line ? 250 : std::uint8_t(25 + 40 * y / h);
      p[2] = disc ? 40 : line ? 250 : std::uint8_t(60 + 60 * y / h);
    }
  return im;
}

void add_noise(RgbaPixels& im, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> d(-3, 3);
  for (std::size_t i = 0; i < im.rgba.size(); ++i)
    if (i % 4 != 3) im.rgba[i] = std::uint8_t(std::clamp(im.rgba[i] + d(rng), 0, 255));
}

void make_synthetic_pairs() {
  for (unsigned k = 0; k < 4; ++k) {
    Pair p{picture(1280, 720, 0), picture(1280, 720, 1)};
    add_noise(p.b, k);
    pairs().push_back(std::move(p));
  }
}

// False (with a message) when a pair is unreadable or its images differ in size.
bool read_pairs(const std::filesystem::path& dir) {
  for (int k = 0;; ++k) {
    std::string stem = std::to_string(k);
    const auto a_path = dir / (stem + "_a.png"), b_path = dir / (stem + "_b.png");
    if (!std::filesystem::exists(a_path)) break;
    auto a = epviz::io::read_png_rgba(a_path), b = epviz::io::read_png_rgba(b_path);
    if (!a || !b || a->width != b->width || a->height != b->height) {
      std::fprintf(stderr, "epviz_ssim_bench: --pairs: cannot read %s and %s as one size\n",
                   a_path.c_str(), b_path.c_str());
      return false;
    }
    pairs().push_back({std::move(*a), std::move(*b)});
  }
  if (pairs().empty()) {
    std::fprintf(stderr, "epviz_ssim_bench: --pairs: no %s/0_a.png\n", dir.c_str());
    return false;
  }
  return true;
}

// One comparison an iteration, through one workspace (as `epviz check` does).
void BM_SsimReusedWorkspace(benchmark::State& state) {
  epviz::check::SsimWorkspace workspace;
  std::size_t k = 0;
  double total = 0;
  for (auto _ : state) {
    const Pair& p = pairs()[k++ % pairs().size()];
    const double s = workspace.ssim(p.a.width, p.a.height, p.a.rgba, p.b.rgba);
    benchmark::DoNotOptimize(s);
    total += s;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["mean_ssim"] = total / double(state.iterations());
}
BENCHMARK(BM_SsimReusedWorkspace)->Unit(benchmark::kMillisecond);

// The same with a fresh workspace each time (check::ssim), for its allocations.
void BM_SsimFreshWorkspace(benchmark::State& state) {
  std::size_t k = 0;
  for (auto _ : state) {
    const Pair& p = pairs()[k++ % pairs().size()];
    benchmark::DoNotOptimize(epviz::check::ssim(p.a.width, p.a.height, p.a.rgba, p.b.rgba));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SsimFreshWorkspace)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  // Take --pairs DIR out before Google Benchmark reads its own flags.
  std::vector<char*> rest{argv[0]};
  std::string pairs_dir;
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--pairs" && i + 1 < argc)
      pairs_dir = argv[++i];
    else
      rest.push_back(argv[i]);
  }
  if (pairs_dir.empty())
    make_synthetic_pairs();
  else if (!read_pairs(pairs_dir))
    return 2;
  int rest_count = int(rest.size());
  benchmark::Initialize(&rest_count, rest.data());
  if (benchmark::ReportUnrecognizedArguments(rest_count, rest.data())) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
