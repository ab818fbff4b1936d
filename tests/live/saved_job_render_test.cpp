// "Save job" saves what was on screen: `epviz render` of the saved job ends
// on the picture the page last showed, compared with `epviz check`'s own
// comparison at its default tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "check/image_compare.hpp"
#include "check/ssim.hpp"
#include "check/tolerance.hpp"
#include "io/png_reader.hpp"
#include "session_driver.hpp"
#include "support/cli.hpp"
#include "support/temp_dir.hpp"

namespace epviz::live::testing {
namespace {

constexpr int kWidth = 640, kHeight = 360;

void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// Blanks a rectangle (frame pixels) of an RGBA picture.
void blank(std::vector<std::uint8_t>& rgba, const Rect& r) {
  const int x0 = std::max(0, int(std::floor(r[0]))), y0 = std::max(0, int(std::floor(r[1])));
  const int x1 = std::min(kWidth, int(std::ceil(r[0] + r[2])));
  const int y1 = std::min(kHeight, int(std::ceil(r[1] + r[3])));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 4; ++c) rgba[(std::size_t(y) * kWidth + x) * 4 + c] = 0;
}

void expect_same_at_default_tolerance(const std::vector<std::uint8_t>& actual,
                                      const std::vector<std::uint8_t>& expected, const char* what) {
  const check::PixelComparison c =
      check::compare_pixels(kWidth, kHeight, actual, expected, check::kDefaultChannelThreshold);
  EXPECT_LE(100.0 * c.fraction_differing(), check::kDefaultMaxDifferingPercent)
      << what << ": " << c.pixels_differing << " of " << c.pixels
      << " pixels differ (largest channel difference " << c.largest_channel_difference << ")";
}

// A session for the saved-job tests: a view narrow enough that the panel
// floats over the scene (as a render lays it out), and a live plan made for
// that size.
SessionOptions small_view(physics::Case c) {
  SessionOptions options = starting_with(c);
  options.initial.scene.width = kWidth;
  options.initial.scene.height = kHeight;
  // The overlay's text describes the run in the words of each: live says
  // the tolerance was chosen (auto), a render also prints its t_end; its
  // window then moves the labels around it. The picture is what must agree.
  options.initial.scene.layers.overlay = false;
  return options;
}

// Plays the session for 45 frames, saves the frame and the job, renders the
// job, and compares the render's last frame with what the page showed; returns the job.
nlohmann::json expect_render_of_saved_job_matches(SessionDriver& d) {
  d.click("play");
  d.frames(45);
  d.click("play");
  EXPECT_FALSE(d.session->scene().playing());
  EXPECT_GT(d.session->scene().time(), 1.0);
  // The last frame the page showed, and the panel over it.
  const std::vector<std::uint8_t> shown = d.session->render().pixels;
  const Rect panel = d.control("panel");
  d.click("save_frame");
  d.click("save_job");
  const auto downloads = d.session->take_downloads();
  if (downloads.size() != 2u) {
    ADD_FAILURE() << downloads.size() << " downloads";
    return {};
  }

  test::TempDir dir;
  write_bytes(dir / "seen.png", downloads[0].bytes);
  write_bytes(dir / "job.json", downloads[1].bytes);
  const auto job = nlohmann::json::parse(downloads[1].bytes.begin(), downloads[1].bytes.end());
  const int frames = int(std::lround(job["fps"].get<double>() * job["duration"].get<double>()));
  const auto r = test::run_epviz("render " + (dir / "job.json").string() + " --frames " +
                                     std::to_string(frames - 1) + " --format png --quiet --out " +
                                     (dir / "out").string(),
                                 dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::optional<io::RgbaPixels> rendered;
  for (const auto& f : std::filesystem::directory_iterator(dir / "out"))
    if (f.path().extension() == ".png") rendered = io::read_png_rgba(f.path());
  if (!rendered || rendered->width != kWidth || rendered->height != kHeight) {
    ADD_FAILURE() << "no frame of " << kWidth << "x" << kHeight << " rendered";
    return job;
  }

  // The whole picture without the panels (what Save frame writes), by
  // structure: the render's run and the live one differ in the last bits
  // (one integrated to t_end, the other without an end), which moves the
  // trail's antialiased edges by a fraction of a pixel and a level or two.
  const auto seen = io::read_png_rgba(dir / "seen.png");
  EXPECT_TRUE(seen);
  if (!seen) return job;
  check::SsimWorkspace ssim;
  EXPECT_GE(ssim.ssim(kWidth, kHeight, rendered->rgba, seen->rgba), check::kDefaultMinSsim);
  // ... and the page's own last frame wherever the panel did not cover it.
  std::vector<std::uint8_t> render_masked = rendered->rgba, shown_masked = shown;
  blank(render_masked, panel);
  blank(shown_masked, panel);
  expect_same_at_default_tolerance(render_masked, shown_masked, "the frame shown");
  return job;
}

TEST(SavedJob, RendersToTheLastFrameShown) {
  SessionDriver d(small_view(physics::Case::kovalevskaya), kWidth, kHeight,
                  /*builtin_font=*/false);
  const auto& v = d.session->view_3d();
  d.wheel(float(v.x + v.width) - 40.0f, float(v.y + v.height) / 2.0f, 2.0f);  // the user's camera
  const auto job = expect_render_of_saved_job_matches(d);
  EXPECT_FALSE(job.contains("runs"));
}

TEST(SavedJob, WithComparedRunsRendersTheSameRuns) {
  SessionOptions options = small_view(physics::Case::generic);
  // The legend names each run's accuracy: live says an automatic tolerance
  // was chosen ("(auto)"), the job gives the number chosen. A tolerance set
  // by hand reads the same in both (as the overlay, hidden above).
  options.initial.scene.auto_tolerance = false;
  options.initial.run.tol = 1e-9;
  // Another method and a nudged state, as the panel adds them.
  options.initial.compared.push_back(with_method(sim::Method::rk4, 0.05, 0.0));
  options.initial.compared.push_back(nudged_by(1e-3));
  SessionDriver d(options, kWidth, kHeight, /*builtin_font=*/false);
  ASSERT_EQ(d.session->scene().run_count(), 3);
  const auto job = expect_render_of_saved_job_matches(d);
  ASSERT_TRUE(job.contains("runs"));
  ASSERT_EQ(job["runs"].size(), 3u);
  EXPECT_EQ(job["runs"][1]["method"], "rk4");
  EXPECT_EQ(job["runs"][1]["step"], 0.05);
  EXPECT_EQ(job["runs"][2]["label"], "nudged 0.001");
  EXPECT_TRUE(job["runs"][2].contains("gamma"));
}

}  // namespace
}  // namespace epviz::live::testing
