// bench JSON -> chart files: a tiny handmade document gives the expected files,
// each a non-blank PNG.
#include <gtest/gtest.h>

#include <filesystem>

#include <stb/stb_image.h>

#include "paint/bench_charts.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

nlohmann::json tiny_bench() {
  using nlohmann::json;
  json rows = json::array();
  for (const char* method : {"rk4", "dop853"})
    for (int k = 0; k < 3; ++k)
      rows.push_back({{"study", "work_precision"}, {"case", "euler"}, {"method", method}, {"formulation", "direct"},
                      {"impl", "epviz"}, {"status", "ok"}, {"error", std::pow(10.0, -3.0 - 2.0 * k)},
                      {"cpu_ms", 0.01 * (k + 1)}, {"rhs_evals", 100.0 * (k + 1)}});
  json t = json::array(), c1 = json::array(), ex = json::array();
  for (int i = 0; i < 20; ++i) {
    t.push_back(5.0 * i);
    c1.push_back(1e-10 * (i + 1));
    ex.push_back(i == 0 ? 0.0 : 1e-9 * i);
  }
  rows.push_back({{"study", "drift"}, {"case", "kovalevskaya"}, {"method", "rk4"}, {"formulation", "direct"},
                  {"impl", "epviz"}, {"series_t", t}, {"series_drift_C1", c1}, {"series_drift_extra", ex}});
  rows.push_back({{"study", "stability_max_step"}, {"case", "kovalevskaya"}, {"method", "rk4"},
                  {"formulation", "direct"}, {"max_step", 0.33}, {"max_step_over_period", 0.084}});
  return {{"metadata", {{"mode", "quick"}}}, {"rows", rows}};
}

TEST(BenchCharts, SpecsFromRows) {
  const auto charts = paint::bench_chart_specs(tiny_bench());
  ASSERT_EQ(charts.size(), 3u);
  EXPECT_EQ(charts[0].file_name, "work_precision_euler.png");
  EXPECT_EQ(charts[0].spec.series.size(), 2u);
  EXPECT_EQ(charts[1].file_name, "work_precision_evals_euler.png");
  EXPECT_EQ(charts[2].file_name, "drift_kovalevskaya.png");
  EXPECT_EQ(charts[2].spec.series.size(), 2u);
  EXPECT_EQ(paint::bench_stability_table(tiny_bench()).rows.size(), 1u);
}

TEST(BenchCharts, WritesNonBlankPngs) {
  testing::shared_gl_context();  // sets LP_NUM_THREADS
  const auto dir = std::filesystem::temp_directory_path() / "epviz_bench_charts_test";
  std::filesystem::remove_all(dir);
  const auto files = paint::write_bench_charts(tiny_bench(), dir, render::gl_backend_from_environment(),
                                               {.width = 480, .height = 300, .msaa_samples = 0, .builtin_font = true});
  ASSERT_EQ(files.size(), 4u);
  for (const char* name : {"work_precision_euler.png", "work_precision_evals_euler.png", "drift_kovalevskaya.png",
                           "stability.png"}) {
    const auto path = dir / name;
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
    ASSERT_NE(data, nullptr) << path;
    int dark = 0;
    for (int i = 0; i < w * h; ++i)
      if (data[i * 4] < 128) ++dark;
    stbi_image_free(data);
    EXPECT_GT(dark, 200) << path;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace epviz
