// A setup saved from the interactive scene is a render job that `epviz
// render` accepts and that reproduces the edited body.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "../app/cli_runner.hpp"
#include "live/job_file.hpp"

namespace epviz::live {
namespace {

TEST(JobFile, EpvizRenderAcceptsTheSavedSetupOfEveryCase) {
  test::TempDir dir;
  for (const auto& p : physics::case_presets()) {
    LiveSetup s = preset_setup(p.id);
    s.run.body.weight = 1.75;  // an edit the job must carry
    s.scene.camera.azimuth_deg = 80.0;
    const auto file = dir / (p.name + ".json");
    std::ofstream(file) << render_job_json(s, p.name, 2.0);
    const auto r = test::run_epviz("render " + file.string() + " --frames 0 --format png --width 160 --height 90 "
                                   "--quiet --out " + (dir / p.name).string(), dir);
    EXPECT_EQ(r.exit_code, 0) << p.name << ": " << r.err;
    bool png_written = false;
    if (std::filesystem::is_directory(dir / p.name))
      for (const auto& f : std::filesystem::directory_iterator(dir / p.name))
        png_written |= f.path().extension() == ".png";
    EXPECT_TRUE(png_written) << p.name;
    const auto j = nlohmann::json::parse(test::slurp(file));
    EXPECT_EQ(j["simulation"]["weight"], 1.75);
    EXPECT_EQ(j["simulation"]["case"], p.name);
    EXPECT_EQ(j["camera"]["azimuth"], 80.0);
  }
}

TEST(JobFile, ABodyOutsideItsCaseIsSavedAsACustomBody) {
  LiveSetup s = preset_setup(physics::Case::kovalevskaya);
  s.run.case_id = physics::Case::custom;
  s.run.body.inertia.z() = 1.3;
  const auto j = nlohmann::json::parse(render_job_json(s, "edited"));
  EXPECT_FALSE(j["simulation"].contains("case"));
  EXPECT_EQ(j["simulation"]["inertia"][2], 1.3);
}

}  // namespace
}  // namespace epviz::live
