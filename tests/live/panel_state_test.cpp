// The panel says what the scene runs and keeps what the user picks: a combo
// pick that arrives with the click that opened the list, opaque lists, the
// formulation actually integrated, a body that left its case, a saved job
// that renders what was seen, and a panel that fits a 1280x720 view.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>

#include "live/job_file.hpp"
#include "physics/cases.hpp"
#include "render/snapshot.hpp"
#include "session_driver.hpp"

namespace epviz::live {
namespace {

using testing::SessionDriver;
using testing::starting_with;

Rect centre_of(const Rect& r) { return {r[0] + r[2] / 2, r[1] + r[3] / 2, 0, 0}; }

TEST(PanelState, AComboPickThatArrivesWithTheOpeningClickIsKept) {
  SessionDriver d(starting_with(physics::Case::generic));
  // Where the list's item is, learnt from opening it once.
  d.click("case");
  ASSERT_TRUE(d.has_control("case:kovalevskaya"));
  const Rect item = centre_of(d.control("case:kovalevskaya"));
  const Rect combo = centre_of(d.control("case"));
  const auto& v = d.session->view_3d();
  d.click_at(float(v.x + v.width) - 40.0f, float(v.y + v.height) - 40.0f);  // closes it
  ASSERT_FALSE(d.has_control("case:kovalevskaya")) << "the list did not close";
  // Open and pick in one batch, before any frame has drawn the list (a slow
  // frame in the browser does this).
  d.move(combo[0], combo[1]);
  d.button(combo[0], combo[1], true);
  d.button(combo[0], combo[1], false);
  d.move(item[0], item[1]);
  d.button(item[0], item[1], true);
  d.button(item[0], item[1], false);
  d.settle(20);
  EXPECT_EQ(d.session->scene().setup().run.case_id, physics::Case::kovalevskaya)
      << "the pick was lost";
}

TEST(PanelState, AnOpenListHidesThePanelBehindIt) {
  SessionDriver d(starting_with(physics::Case::hess));
  d.click("case");
  const Rect list = d.control("list:case");
  const Rect current = d.control("case:hess");  // highlighted: skipped
  const Rect combo = d.control("case");
  const render::RgbaImage& img = d.session->render();
  // A column near the list's right edge, where no item text is, over the
  // panel's sliders and labels: an opaque list shows one colour there.
  const int x = int(list[0] + list[2]) - 3;
  std::set<std::uint32_t> colours;
  for (int y = int(list[1]) + 3; y < int(list[1] + list[3]) - 3; ++y) {
    if (y >= int(current[1]) - 1 && y <= int(current[1] + current[3]) + 1) continue;
    const glm::u8vec4 c = img.at(x, y);
    colours.insert(std::uint32_t(c.r) << 16 | std::uint32_t(c.g) << 8 | c.b);
  }
  ASSERT_GT(list[1], combo[1]) << "the list is not below the combo";
  EXPECT_EQ(colours.size(), 1u) << "what is behind the list shows through it";
}

TEST(PanelState, TheFormulationBoxShowsTheOneIntegrated) {
  // The Lagrange job views space, which only the spinor form can draw.
  SessionOptions o = starting_with(physics::Case::lagrange);
  o.initial.scene.view = scene::View::space;
  o.initial.run.formulation = sim::Formulation::direct;
  o.initial.scene.formulation_given = false;
  SessionDriver d(o);
  ASSERT_EQ(d.session->scene().formulation(), sim::Formulation::spinor);
  d.click("header:integrator");
  d.click("formulation");
  ASSERT_TRUE(d.has_control("formulation:spinor"));
  // The list marks the running formulation; its preview text is the same name.
  const auto& controls = d.session->panel().controls();
  EXPECT_TRUE(controls.count("formulation:direct"));
  EXPECT_EQ(d.session->panel().shown_formulation(), sim::Formulation::spinor);
}

TEST(PanelState, ABodyThatLeftItsCaseSaysWhichConditionItBroke) {
  SessionOptions o = starting_with(physics::Case::kovalevskaya);
  o.initial.scene.title = "Kovalevskaya top";
  SessionDriver d(o);
  d.click("stay");
  ASSERT_FALSE(d.session->scene().setup().stay_in_case);
  const Rect r = d.control("I3");
  d.drag(r[0] + r[2] / 2, r[1] + r[3] / 2, 60.0f, 0.0f);
  const LiveSetup& s = d.session->scene().setup();
  ASSERT_EQ(s.run.case_id, physics::Case::custom);
  EXPECT_TRUE(s.scene.title.empty()) << "the title still names the case: " << s.scene.title;
  EXPECT_TRUE(d.has_control("broken")) << "no broken condition is shown";
}

TEST(PanelState, SaveJobKeepsTheTimeTheCameraAndTheLiveTolerance) {
  SessionDriver d(starting_with(physics::Case::kovalevskaya));
  const auto& v = d.session->view_3d();
  const float x = float(v.x + v.width) - 60.0f, y = float(v.y + v.height) / 2.0f;
  d.drag(x, y, -80.0f, 30.0f);  // a camera of the user's own
  d.click("play");
  d.frames(60);
  d.click("play");
  const double t = d.session->scene().time();
  ASSERT_GT(t, 1.0);
  d.click("save_job");
  const auto downloads = d.session->take_downloads();
  ASSERT_EQ(downloads.size(), 1u);
  const auto job = nlohmann::json::parse(downloads[0].bytes.begin(), downloads[0].bytes.end());
  const LiveSetup& s = d.session->scene().setup();
  EXPECT_EQ(job["camera"]["azimuth"], s.scene.camera.azimuth_deg);
  EXPECT_EQ(job["camera"]["elevation"], s.scene.camera.elevation_deg);
  EXPECT_EQ(job["camera"]["distance"], s.scene.camera.distance);
  // The tolerance as a number, the live scene's own (its note prints it).
  ASSERT_TRUE(job["simulation"]["tol"].is_number()) << job.dump();
  char printed[32];
  std::snprintf(printed, sizeof printed, "tol %.2g", job["simulation"]["tol"].get<double>());
  EXPECT_EQ(d.session->scene().accuracy_note().rfind(printed, 0), 0u)
      << printed << " vs the live " << d.session->scene().accuracy_note();
  // What was watched: from t = 0, where the run started, to the moment
  // shown, at the live speed (not a t_end extrapolated beyond it).
  EXPECT_DOUBLE_EQ(job["simulation"]["t_end"].get<double>(), t);
  // Frames 1/fps apart at the live speed, the first at t = 0, the last at t.
  const double fps = job["fps"];
  const double frames = std::round(fps * job["duration"].get<double>());
  EXPECT_NEAR((frames - 1) / fps * s.speed, t, 1e-9 * t);
  EXPECT_EQ(job["width"], 960);
  EXPECT_EQ(job["height"], 540);
  bool said = false;
  for (const auto& n : d.session->take_notices())
    said |= n.find("from t = 0, where this run started") != std::string::npos;
  EXPECT_TRUE(said) << "the user is not told the job starts at t = 0";
}

TEST(PanelState, EverySaveControlIsInSightAt1280x720) {
  SessionDriver d(starting_with(physics::Case::kovalevskaya), 1280, 720);
  const Rect panel = d.control("panel");
  EXPECT_LE(panel[1] + panel[3], 720.0f);
  for (const char* name : {"save_frame", "save_job", "file_name"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(d.has_control(name));
    const Rect r = d.control(name);
    EXPECT_LE(r[1] + r[3], std::min(720.0f, panel[1] + panel[3])) << "below the fold";
  }
  const auto& img = d.session->render();
  EXPECT_TRUE(
      epviz::testing::matches_snapshot("live_panels_1280x720", img.width, img.height, img.pixels));
}

}  // namespace
}  // namespace epviz::live
