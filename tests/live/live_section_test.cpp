// The live mode's section panel: shown from the panel, filled from the run's
// own steps as it plays, a click on it starting an orbit from that point on
// the run's level (or saying why none starts), and "Save job" keeping the
// orbits so that a render of the job draws the same crossings.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "job/job_file.hpp"
#include "job/job_plan.hpp"
#include "job/schema.hpp"
#include "physics/direct.hpp"
#include "physics/invariants.hpp"
#include "scene/frame_source.hpp"
#include "session_driver.hpp"
#include "sim/section_chart_inverse.hpp"
#include "support/temp_dir.hpp"

namespace epviz::live::testing {
namespace {

// Four times the live default speed: a frame covers 4/30 s of simulation
// time, so that the tests reach the crossings they need in a quarter of the
// frames (each frame is drawn, at 960 x 540).
constexpr double kSpeed = 16.0;

// A Kovalevskaya top at kSpeed.
SessionOptions kovalevskaya() {
  SessionOptions o = starting_with(physics::Case::kovalevskaya);
  o.initial.speed = kSpeed;
  return o;
}

// The same with the section panel (gamma3 = 0 upward at (gamma1, Omega3)).
SessionOptions with_section() {
  SessionOptions o = kovalevskaya();
  o.initial.scene.section = scene::SectionPanelSettings{};
  return o;
}

// Plays `frames` frames and pauses, the case's part of the panel closed so
// that the section's controls come into its view.
void play_then_pause(SessionDriver& d, int frames) {
  d.click("header:case");
  d.click("play");
  d.frames(frames);
  d.click("play");
}

// The picture's pixel of the panel's point (x, y): the forward map of the plot.
std::pair<float, float> pixel_of(const LiveSession& s, double x, double y) {
  const auto& a = *s.layout().section_area;
  const auto& r = s.scene().frame().section->range;
  return {float(a.x + (x - r[0]) / (r[1] - r[0]) * a.width),
          float(a.y + (1.0 - (y - r[2]) / (r[3] - r[2])) * a.height)};
}

// Every crossing lies on gamma3 = 0, crosses it upward (by the direct
// equations' right-hand side) and keeps the level of the run it belongs to.
void expect_crossings_of_level(const physics::Body& body, const physics::Level& level,
                               const std::vector<sim::Crossing>& crossings) {
  physics::DirectSystem sys(body);
  for (const auto& c : crossings) {
    EXPECT_LE(std::abs(c.gamma.z()), 1e-12) << "crossing " << c.number;
    physics::DirectSystem::State x, dx;
    x << c.omega, c.gamma;
    sys.rhs(0.0, x, dx);
    EXPECT_GT(dx[5], 0.0) << "crossing " << c.number;
    const auto inv = physics::invariants(body, physics::Case::custom, c.omega, c.gamma);
    EXPECT_NEAR(inv.energy, level.energy, 1e-6 * std::max(1.0, std::abs(level.energy)));
    EXPECT_NEAR(inv.area, level.area, 1e-6 * std::max(1.0, std::abs(level.area)));
  }
}

// The oracle of the sheet drawn: how many of `crossings`, by the gamma2 of
// each one's own state, lie on the sheet of sign `sign` (the fold, gamma2 =
// 0, on both) and how many on the other.
std::pair<std::size_t, std::size_t> on_and_off_sheet(const std::vector<sim::Crossing>& crossings,
                                                     int sign) {
  std::size_t on = 0, off = 0;
  for (const auto& c : crossings) (sign * c.gamma.y() >= 0.0 ? on : off) += 1;
  return {on, off};
}

TEST(LiveSection, ShownFromThePanelAndFilledAsTheRunPlays) {
  SessionDriver d(kovalevskaya());
  EXPECT_FALSE(d.session->scene().frame().section);
  EXPECT_FALSE(d.session->layout().section_area);
  d.click("header:section");
  d.click("section");
  ASSERT_TRUE(d.session->scene().section());
  ASSERT_TRUE(d.session->scene().frame().section);
  ASSERT_TRUE(d.session->layout().section_area) << "the frame is laid out with the panel";
  d.click("play");
  d.frames(38);
  d.click("play");
  const LiveSection& section = *d.session->scene().section();
  const auto& crossings = section.run_crossings(0);
  ASSERT_GE(crossings.size(), 2u) << "t = " << d.session->scene().time();
  expect_crossings_of_level(d.session->scene().setup().run.body, section.level(), crossings);
  // The frame shows those of the sheet drawn (gamma2 > 0 by default) and
  // counts the others: the scene's time is past every one found.
  const auto [on, off] = on_and_off_sheet(crossings, 1);
  EXPECT_EQ(d.session->scene().frame().section->runs.at(0).size(), on);
  EXPECT_EQ(d.session->scene().frame().section->hidden, off);
  const auto c = nlohmann::json::parse(d.session->controls_json());
  EXPECT_EQ(c["section"]["plot"].size(), 4u);
  EXPECT_EQ(c["section"]["dots"][0], on);
  // Switched off, the panel goes.
  d.click("section");
  EXPECT_FALSE(d.session->scene().frame().section);
}

TEST(LiveSection, AClickOnThePanelStartsAnOrbitWhoseCrossingsFillIn) {
  SessionDriver d(with_section());
  play_then_pause(d, 38);
  const LiveSection& section = *d.session->scene().section();
  ASSERT_GE(section.run_crossings(0).size(), 1u);
  // A point of the level: the run's first crossing, on the sheet it lies on.
  const sim::Crossing& at = section.run_crossings(0).front();
  if (at.gamma.y() < 0.0) d.click("sheet:-");
  EXPECT_EQ(d.session->panel().click_sheet(), at.gamma.y() < 0.0 ? -1 : 1);
  (void)d.session->take_notices();
  const auto [px, py] = pixel_of(*d.session, at.gamma.x(), at.omega.z());
  d.click_at(px, py);
  ASSERT_EQ(section.orbit_count(), 1) << d.session->panel().message();
  const auto notices = d.session->take_notices();
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_NE(notices[0].find("orbit 1 from"), std::string::npos) << notices[0];
  EXPECT_FALSE(d.session->panel().message_is_error());
  // Paused, the orbit catches up to the scene's time frame by frame.
  d.settle(400);
  EXPECT_FALSE(d.session->scene().section_filling());
  const auto& orbit = section.orbit(0);
  EXPECT_NEAR(orbit.time(), d.session->scene().time(), d.session->scene().sample_spacing());
  ASSERT_GE(orbit.crossings().size(), 2u) << "its start and at least one crossing";
  // Started within a pixel of the run's own crossing, on its level.
  const auto& start = orbit.crossings().front();
  EXPECT_EQ(start.t, 0.0);
  EXPECT_NEAR(start.gamma.x(), at.gamma.x(), 0.02);
  EXPECT_NEAR(start.omega.z(), at.omega.z(), 0.05);
  expect_crossings_of_level(d.session->scene().setup().run.body, section.level(),
                            orbit.crossings());
  // Drawn: the panel's second list is the orbit's, every crossing up to its
  // time on the sheet drawn, which is the sheet it started on.
  const auto& panel = *d.session->scene().frame().section;
  ASSERT_EQ(panel.runs.size(), 2u);
  const int sign = d.session->panel().click_sheet();
  EXPECT_EQ(d.session->scene().setup().scene.section->sheet->sign, sign);
  EXPECT_GE(sign * start.gamma.y(), 0.0);
  EXPECT_EQ(panel.runs[1].size(), on_and_off_sheet(orbit.crossings(), sign).first);
  EXPECT_NE(panel.colours[1], panel.colours[0]);
  // Kept in the setup (a restart runs it again), and cleared by the button.
  EXPECT_EQ(d.session->scene().setup().scene.section->orbits.size(), 1u);
  d.click("clear_orbits");
  EXPECT_EQ(section.orbit_count(), 0);
  EXPECT_TRUE(d.session->scene().setup().scene.section->orbits.empty());
}

TEST(LiveSection, TheSheetButtonsChooseTheSheetDrawn) {
  SessionDriver d(with_section());
  play_then_pause(d, 75);
  const LiveSection& section = *d.session->scene().section();
  const auto& run = section.run_crossings(0);
  for (int sign : {-1, 1}) {
    SCOPED_TRACE(sign);
    d.click(sign > 0 ? "sheet:+" : "sheet:-");
    d.frames(2);
    EXPECT_EQ(section.settings().sheet, (scene::SectionSheet{sim::StateComponent::gamma2, sign}));
    EXPECT_EQ(d.session->scene().setup().scene.section->sheet, section.settings().sheet);
    const auto& panel = *d.session->scene().frame().section;
    const auto [on, off] = on_and_off_sheet(run, sign);
    // (The preset's run may cross on one sheet only: then one button shows
    // every crossing and the other none, each counted.)
    ASSERT_GT(on + off, 0u);
    // Each dot drawn is a crossing of the asked sign, and every one of them is drawn.
    ASSERT_EQ(panel.runs.at(0).size(), on);
    std::size_t k = 0;
    for (const auto& c : run) {
      if (sign * c.gamma.y() < 0.0) continue;
      EXPECT_EQ(panel.runs[0][k], Eigen::Vector2d(c.gamma.x(), c.omega.z()));
      ++k;
    }
    EXPECT_EQ(panel.hidden, off);
    EXPECT_NE(panel.title.find(sign > 0 ? "γ₂ > 0" : "γ₂ < 0"), std::string::npos) << panel.title;
    if (off > 0)
      EXPECT_NE(panel.note.find(std::to_string(off) + " crossing"), std::string::npos)
          << panel.note;
    else
      EXPECT_EQ(panel.note, "");
  }
}

TEST(LiveSection, AClickWithAStateOnTheOtherSheetOnlyIsRefused) {
  // A body with I1 != I2: with I1 = I2 (Kovalevskaya) the level's two states
  // on a sheet at a point cross in opposite directions, and the other
  // sheet's are their mirror images, so every point has one on each sheet.
  SessionOptions o = starting_with(physics::Case::generic);
  o.initial.scene.section = scene::SectionPanelSettings{};
  LiveSetup setup = o.initial;
  LiveScene scene(setup);
  const LiveSection& section = *scene.section();
  const auto& run = scene.setup().run;
  const auto& r = scene.frame().section->range;
  // A point of the plot where the level has a state crossing upward on one
  // sheet but none on the other (the direction of crossing tells them apart).
  std::optional<std::pair<double, double>> point;
  int empty_sheet = 0;
  const auto& s = section.settings();
  for (int i = 1; i < 120 && !point; ++i)
    for (int j = 1; j < 120 && !point; ++j) {
      const double x = r[0] + (r[1] - r[0]) * i / 120.0, y = r[2] + (r[3] - r[2]) * j / 120.0;
      for (int sign : {1, -1}) {
        if (sim::section_states_at(run.body, section.level(), s.surface, s.coords, x, y, sign)
                .states.empty() &&
            !sim::section_states_at(run.body, section.level(), s.surface, s.coords, x, y, -sign)
                 .states.empty()) {
          point = {x, y};
          empty_sheet = sign;
          break;
        }
      }
    }
  ASSERT_TRUE(point);
  const auto refused = scene.add_section_orbit(point->first, point->second, empty_sheet);
  EXPECT_FALSE(refused.added);
  EXPECT_EQ(refused.notice, std::string("no state on this sheet at that point; try ") +
                                (empty_sheet > 0 ? "γ₂ < 0" : "γ₂ > 0"));
  EXPECT_EQ(scene.section()->orbit_count(), 0);
  // On the sheet that has one, it starts there.
  const auto added = scene.add_section_orbit(point->first, point->second, -empty_sheet);
  ASSERT_TRUE(added.added) << added.notice;
  EXPECT_LT(empty_sheet * scene.section()->orbit(0).crossings().front().gamma.y(), 0.0);
}

// A served job's section.sheet is the sheet drawn and the sheet a click
// starts on, without a press of the sheet buttons.
TEST(LiveSection, AJobsSheetIsDrawnAndClickedOn) {
  test::TempDir dir;
  const auto file = dir.write("job.json", R"({
    "simulation": {"case": "kovalevskaya", "t_end": 200},
    "section": {"sheet": "gamma2 < 0"},
    "width": 320, "height": 180, "fps": 10, "duration": 2})");
  SessionOptions o = starting_with(physics::Case::kovalevskaya);
  o.initial = setup_from_job_file(file);
  SessionDriver d(o);
  ASSERT_TRUE(d.session->scene().section());
  EXPECT_EQ(d.session->scene().section()->settings().sheet,
            (scene::SectionSheet{sim::StateComponent::gamma2, -1}));
  d.click("play");
  d.frames(38);  // at the job's speed, 100: to t = 127 or so
  d.click("play");
  const LiveSection& section = *d.session->scene().section();
  const auto& run = section.run_crossings(0);
  const auto [on, off] = on_and_off_sheet(run, -1);
  ASSERT_GT(on, 0u);
  EXPECT_EQ(d.session->scene().frame().section->runs.at(0).size(), on);
  EXPECT_EQ(d.session->scene().frame().section->hidden, off);
  // A click at a crossing of the run on that sheet starts an orbit there.
  sim::Crossing at;
  for (const auto& c : run)
    if (c.gamma.y() < 0.0) at = c;
  const auto [px, py] = pixel_of(*d.session, at.gamma.x(), at.omega.z());
  d.click_at(px, py);
  ASSERT_EQ(section.orbit_count(), 1) << d.session->panel().message();
  EXPECT_LT(section.orbit(0).crossings().front().gamma.y(), 0.0);
}

// Started exactly at the run's k-th crossing, an orbit is the run itself
// shifted in time: its crossings are the run's next ones.
TEST(LiveSection, AnOrbitFromTheRunsOwnCrossingRetracesTheRun) {
  LiveSetup setup = with_section().initial;
  LiveScene scene(setup);
  scene.set_playing(true);
  for (int i = 0; i < 300; ++i) scene.update(1.0 / 30.0);
  scene.set_playing(false);
  const auto run = scene.section()->run_crossings(0);
  ASSERT_GE(run.size(), 2u);
  const sim::Crossing& k = run.front();
  const auto added = scene.add_section_orbit(k.gamma.x(), k.omega.z(), k.gamma.y() > 0 ? 1 : -1);
  ASSERT_TRUE(added.added) << added.notice;
  for (int i = 0; i < 400 && scene.section_filling(); ++i) scene.update(1.0 / 30.0);
  const auto& orbit = scene.section()->orbit(0).crossings();
  ASSERT_GE(orbit.size(), 2u);
  // The same point of the panel; the rest of the state from the run's
  // level, which the crossing keeps to the run's drift (1e-8 or so).
  EXPECT_EQ(orbit[0].gamma.x(), k.gamma.x());
  EXPECT_EQ(orbit[0].omega.z(), k.omega.z());
  EXPECT_LT((orbit[0].omega - k.omega).norm(), 1e-6);
  EXPECT_LT((orbit[0].gamma - k.gamma).norm(), 1e-6);
  for (std::size_t j = 1; j < orbit.size() && j < run.size(); ++j) {
    EXPECT_NEAR(orbit[j].t + k.t, run[j].t, 1e-4) << j;
    EXPECT_LT((orbit[j].gamma - run[j].gamma).norm(), 1e-4) << j;
    EXPECT_LT((orbit[j].omega - run[j].omega).norm(), 1e-4) << j;
  }
}

TEST(LiveSection, AClickWhereTheLevelHasNoStateSaysSo) {
  SessionDriver d(with_section());
  const auto& r = d.session->scene().frame().section->range;
  (void)d.session->take_notices();
  // gamma1 beyond 1 (the plot's margin right of the level's reach): no unit gamma on gamma3 = 0.
  const auto [px, py] = pixel_of(*d.session, 0.5 * (1.0 + r[1]), 0.0);
  d.click_at(px, py);
  EXPECT_EQ(d.session->scene().section()->orbit_count(), 0);
  const auto notices = d.session->take_notices();
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_NE(notices[0].find("no orbit started"), std::string::npos) << notices[0];
  EXPECT_TRUE(d.session->panel().message_is_error());
  // Omega3 at the top of the plot: more kinetic energy than the level has.
  const auto [qx, qy] = pixel_of(*d.session, 0.0, 0.99 * r[3]);
  d.click_at(qx, qy);
  EXPECT_EQ(d.session->scene().section()->orbit_count(), 0);
  const auto more = d.session->take_notices();
  ASSERT_EQ(more.size(), 1u);
  EXPECT_NE(more[0].find("lacks"), std::string::npos) << more[0];
  // Not a camera drag either.
  EXPECT_FALSE(d.session->dragging());
}

TEST(LiveSection, SaveJobKeepsTheOrbitsAndARenderDrawsTheirCrossings) {
  SessionDriver d(with_section());
  play_then_pause(d, 38);
  const LiveSection& section = *d.session->scene().section();
  ASSERT_GE(section.run_crossings(0).size(), 1u);
  const sim::Crossing& at = section.run_crossings(0).front();
  // A point near the run's crossing, on the other sheet: another orbit.
  if (at.gamma.y() > 0.0) d.click("sheet:-");
  const auto [px, py] = pixel_of(*d.session, 0.9 * at.gamma.x(), at.omega.z());
  d.click_at(px, py);
  ASSERT_EQ(section.orbit_count(), 1) << d.session->panel().message();
  d.settle(400);
  ASSERT_FALSE(d.session->scene().section_filling());
  (void)d.session->take_downloads();
  d.click("save_job");
  const auto downloads = d.session->take_downloads();
  ASSERT_EQ(downloads.size(), 1u) << d.session->panel().message();
  const auto json = nlohmann::json::parse(downloads[0].bytes.begin(), downloads[0].bytes.end());
  ASSERT_EQ(json["section"]["orbits"].size(), 1u) << json.dump();
  const auto& start = section.orbit(0).crossings().front();
  EXPECT_EQ(json["section"]["orbits"][0]["omega"][2].get<double>(), start.omega.z());
  EXPECT_EQ(json["section"]["orbits"][0]["gamma"][0].get<double>(), start.gamma.x());

  // The job as `epviz render` reads and plans it; its last frame's panel.
  job::JobDocument doc = job::read_job(json, "saved.json");
  job::RenderJob job{"saved.json", std::move(doc.simulation), std::move(doc.runs),
                     std::move(doc.scene), std::move(doc.output)};
  const scene::ScenePlan plan = job::plan_job(job);
  scene::FrameSource source(plan, job.scene);
  const scene::Frame last = source.frame(plan.frames - 1);
  ASSERT_TRUE(last.section);
  const auto& live = *d.session->scene().frame().section;
  ASSERT_EQ(last.section->runs.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& a = live.runs[i];
    const auto& b = last.section->runs[i];
    // The same crossings; the last may fall either side of the end by rounding.
    EXPECT_LE(std::abs(long(a.size()) - long(b.size())), 1) << "list " << i;
    // The run's may all lie on the sheet not drawn; the clicked orbit starts on the drawn one.
    if (i == 1) {
      EXPECT_GE(b.size(), 2u) << "list " << i;
    }
    for (std::size_t j = 0; j < std::min(a.size(), b.size()); ++j)
      EXPECT_LT((a[j] - b[j]).norm(), 1e-6) << "list " << i << " crossing " << j;
  }
  EXPECT_NE(last.section->colours[1], last.section->colours[0]);
  // The sheet drawn is saved, and the render counts what it leaves out as the live panel does.
  EXPECT_EQ(json["section"]["sheet"],
            d.session->panel().click_sheet() > 0 ? "gamma2 > 0" : "gamma2 < 0");
  EXPECT_EQ(job.scene.section->sheet, d.session->scene().section()->settings().sheet);
  EXPECT_LE(std::abs(long(last.section->hidden) - long(live.hidden)), 2);
  EXPECT_EQ(last.section->hidden + last.section->runs[0].size() + last.section->runs[1].size(),
            section.run_crossings(0).size() + section.orbit(0).crossings().size())
      << "every crossing drawn or counted";
}

// `epviz serve JOB`: a job's "section" shows the panel from the start, and
// its orbits start again (the saved job of a session with clicked orbits).
TEST(LiveSection, AJobsSectionShowsThePanelWithItsOrbits) {
  test::TempDir dir;
  const auto file = dir.write("job.json", R"({
    "simulation": {"case": "kovalevskaya", "t_end": 20},
    "section": {"orbits": [{"omega": [-0.4, 0.9, 0.3], "gamma": [0.6, 0.8, 0.0]}]},
    "width": 320, "height": 180, "fps": 10, "duration": 2})");
  LiveScene scene(setup_from_job_file(file));
  ASSERT_TRUE(scene.section());
  ASSERT_TRUE(scene.frame().section);
  ASSERT_EQ(scene.section()->orbit_count(), 1);
  EXPECT_EQ(scene.section()->orbit(0).crossings().front().omega, Eigen::Vector3d(-0.4, 0.9, 0.3));
  // A job without one has no panel.
  const auto plain = dir.write("plain.json", R"({
    "simulation": {"case": "kovalevskaya", "t_end": 20},
    "width": 320, "height": 180, "fps": 10, "duration": 2})");
  EXPECT_FALSE(LiveScene(setup_from_job_file(plain)).section());
}

}  // namespace
}  // namespace epviz::live::testing
