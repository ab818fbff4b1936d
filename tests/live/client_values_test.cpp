// What a browser tab types is checked before the scene takes it: a value
// beyond its range (the field table's for a job field, the panel's own for
// speed, trail and nudge) is refused with a message in the panel, whatever
// the slider's ends; "Save job" sends only a job that `epviz render` accepts.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>

#include "job/fields.hpp"
#include "job/job_file.hpp"
#include "job/job_plan.hpp"
#include "live/job_file.hpp"
#include "live/setup_limits.hpp"
#include "session_driver.hpp"
#include "support/temp_dir.hpp"

namespace epviz::live::testing {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The job the download holds, through the job reader from a file, as `epviz render` reads it.
void expect_render_reads(const serve::Download& download) {
  test::TempDir dir;
  const auto file = dir / download.name;
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(download.bytes.data()),
             std::streamsize(download.bytes.size()));
  try {
    const job::LoadedJob loaded = job::load_job_file(file);
    ASSERT_TRUE(loaded.single.has_value());
    (void)job::plan_job(*loaded.single);
    check_render_accepts(std::string(download.bytes.begin(), download.bytes.end()), download.name);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "the saved job is refused: " << e.what();
  }
}

TEST(ClientValues, EveryNumberOutsideItsRangeIsRefusedNamingTheRange) {
  const LiveSetup current = preset_setup(physics::Case::kovalevskaya);
  EXPECT_FALSE(out_of_range(current, current));
  struct Case {
    const char* what;
    std::function<void(LiveSetup&)> edit;
    std::string range;  // as the message must word it
  };
  const auto table = [](const char* key) { return job::find_field(key)->range_text(); };
  std::vector<Case> cases;
  for (double bad : {kNan, kInf, -kInf, 1e300, -1e300}) {
    cases.push_back(
        {"inertia", [=](LiveSetup& s) { s.run.body.inertia[1] = bad; }, table("inertia")});
    cases.push_back({"com", [=](LiveSetup& s) { s.run.body.com[2] = bad; }, table("com")});
    cases.push_back({"weight", [=](LiveSetup& s) { s.run.body.weight = bad; }, table("weight")});
    cases.push_back({"omega", [=](LiveSetup& s) { s.run.initial.omega[0] = bad; }, table("omega")});
    cases.push_back({"gamma", [=](LiveSetup& s) { s.run.initial.gamma[2] = bad; }, table("gamma")});
    cases.push_back({"tol", [=](LiveSetup& s) { s.run.tol = bad; }, table("tol")});
    cases.push_back({"step", [=](LiveSetup& s) { s.run.step = -std::abs(bad); }, table("step")});
    cases.push_back({"speed", [=](LiveSetup& s) { s.speed = bad; }, "a number from 0.05 to 100"});
    cases.push_back({"trail length", [=](LiveSetup& s) { s.scene.trail_length = bad; },
                     "a number from 0.5 to 1000"});
    cases.push_back(
        {"tol",
         [=](LiveSetup& s) { s.compared.push_back(with_method(sim::Method::dopri5, 0.1, bad)); },
         table("tol")});
    cases.push_back({"step",
                     [=](LiveSetup& s) {
                       s.compared.push_back(with_method(sim::Method::rk4, -std::abs(bad), 1e-8));
                     },
                     table("step")});
    cases.push_back({"nudge", [=](LiveSetup& s) { s.compared.push_back(nudged_by(bad)); },
                     "a number from 1e-12 to 0.1"});
  }
  cases.push_back({"tol", [](LiveSetup& s) { s.run.tol = 0.2; }, table("tol")});
  cases.push_back({"step", [](LiveSetup& s) { s.run.step = 0.0; }, table("step")});
  cases.push_back({"speed", [](LiveSetup& s) { s.speed = 1e-300; }, "a number from 0.05 to 100"});
  for (const Case& c : cases) {
    LiveSetup edited = current;
    c.edit(edited);
    const auto why = out_of_range(edited, current);
    SCOPED_TRACE(c.what);
    ASSERT_TRUE(why.has_value());
    EXPECT_EQ(why->rfind(c.what, 0), 0u) << *why;
    EXPECT_TRUE(contains(*why, "(" + c.range + ")")) << *why;
  }
  // The bounds of the table themselves are in range; a value the setup
  // already had (a served job's speed, say) is not checked again.
  LiveSetup edge = current;
  edge.run.tol = job::max_tol;
  edge.speed = kMaxSpeed;
  EXPECT_FALSE(out_of_range(edge, current));
  LiveSetup served = current;
  served.speed = 400.0;
  LiveSetup layered = served;
  layered.scene.layers.sphere = false;
  EXPECT_FALSE(out_of_range(layered, served));
}

TEST(ClientValues, TypedValuesPastTheSlidersAreRefusedInThePanel) {
  SessionDriver d(starting_with(physics::Case::kovalevskaya));
  // ImGui applies a typed number as it is typed ("1", "1e", "1e3", ...):
  // the prefixes in range are taken, the rest refused. So the scene must
  // never run with a value out of range, and the panel must say why.
  LiveSetup unknown = d.session->scene().setup();  // NaN everywhere: every value is checked
  for (double* v : {&unknown.run.body.weight, &unknown.run.tol, &unknown.run.step, &unknown.speed,
                    &unknown.scene.trail_length})
    *v = kNan;
  for (Eigen::Vector3d* v : {&unknown.run.body.inertia, &unknown.run.body.com,
                             &unknown.run.initial.omega, &unknown.run.initial.gamma})
    v->setConstant(kNan);
  auto expect_refused = [&](const char* what, const std::string& field) {
    SCOPED_TRACE(what);
    const std::string& message = d.session->panel().message();
    EXPECT_TRUE(d.session->panel().message_is_error()) << message;
    EXPECT_EQ(message.rfind("not applied: " + field + " ", 0), 0u) << message;
    const LiveSetup& now = d.session->scene().setup();
    const auto why = out_of_range(now, unknown);
    EXPECT_FALSE(why) << "the scene runs with " << *why;
  };
  d.type_into("speed", "1e300");
  expect_refused("speed 1e300", "speed");
  d.type_into("speed", "1e-300");
  expect_refused("speed 1e-300", "speed");
  d.type_into("I2", "1e999");  // inf
  expect_refused("I2 inf", "inertia");
  // The weight box takes Enter: its text selected first.
  const Rect w = d.control("weight");
  d.click_at(w[0] + w[2] * 0.3f, w[1] + w[3] / 2);
  d.key("a", true);
  d.type("-1e300");
  d.key("Enter");
  d.settle();
  expect_refused("weight -1e300", "weight");
  d.click("header:case");  // closed: room below for the other sections
  d.click("header:drift");
  d.click("header:integrator");
  d.click("auto_tol");
  ASSERT_FALSE(d.session->scene().setup().scene.auto_tolerance);
  d.type_into("run_tol", "1e300");
  expect_refused("tol 1e300", "tol");
  d.click("header:integrator");
  d.click("header:view");
  d.type_into("trail", "1e300");
  expect_refused("trail 1e300", "trail length");
  // A compared run's tolerance and nudge: refused when the run is added.
  d.click("header:view");
  d.click("header:runs");
  d.type_into("new_tol", "1e300");
  d.click("add_run");
  expect_refused("compared tol 1e300", "tol");
  d.type_into("nudge", "1e300");
  d.click("add_nudged");
  expect_refused("nudge 1e300", "nudge");
}

TEST(ClientValues, SaveJobSendsOnlyJobsTheJobReaderAccepts) {
  // An odd page size (the job's MP4 needs an even one), a compared RK4 run
  // at a step far below the slider's, a tol typed beyond the table's range.
  SessionOptions o = starting_with(physics::Case::generic);
  SessionDriver d(o, 961, 541);
  d.click("header:case");  // closed: room below for the runs
  d.click("header:drift");
  d.click("header:runs");
  d.click("new_method");
  d.click("new_method:rk4");
  d.type_into("new_step", "1e-9");
  d.click("add_run");
  ASSERT_EQ(d.session->scene().run_count(), 2) << d.session->panel().message();
  d.click("new_method");
  d.click("new_method:dopri5");
  d.type_into("new_tol", "1e300");
  d.click("add_run");
  ASSERT_EQ(d.session->scene().run_count(), 2);
  d.click("play");
  d.frames(5);
  d.click("play");
  d.click("save_job");
  auto downloads = d.session->take_downloads();
  ASSERT_EQ(downloads.size(), 1u) << d.session->panel().message();
  expect_render_reads(downloads[0]);
  const auto job = nlohmann::json::parse(downloads[0].bytes.begin(), downloads[0].bytes.end());
  EXPECT_EQ(job["width"].get<int>() % 2, 0);
  EXPECT_EQ(job["height"].get<int>() % 2, 0);
  EXPECT_NEAR(job["width"].get<double>(), 961, 1);

  // A name the job's output cannot have: nothing is sent, the panel says why.
  const Rect name = d.control("file_name");
  d.click_at(name[0] + name[2] / 2, name[1] + name[3] / 2);
  d.key("a", true);
  d.type("..");
  d.key("Enter");
  d.settle();
  ASSERT_EQ(d.session->panel().save_name(), "..");
  d.click("save_job");
  EXPECT_TRUE(d.session->take_downloads().empty());
  const std::string& message = d.session->panel().message();
  EXPECT_EQ(message.rfind("not saved: ", 0), 0u) << message;
  EXPECT_TRUE(contains(message, "output.name")) << message;
}

TEST(ClientValues, ARunTooCostlyForItsSpeedTakesABoundedShareOfEachFrame) {
  struct Costly {
    const char* what;
    LiveSetup setup;
  };
  std::vector<Costly> setups;
  {
    LiveSetup s = preset_setup(physics::Case::generic);
    s.compared.push_back(with_method(sim::Method::rk4, 1e-9, 0.0));
    setups.push_back({"a compared RK4 run at step 1e-9", s});
  }
  {
    LiveSetup s = preset_setup(physics::Case::generic);
    s.compared.push_back(with_method(sim::Method::gauss6, 1e-9, 0.0));
    setups.push_back({"a compared Gauss 6 run at step 1e-9 (implicit: the costliest step)", s});
  }
  {
    // A fast body at the tightest tolerance the table allows: thousands of
    // DOP853 steps per unit of time.
    LiveSetup s = preset_setup(physics::Case::generic);
    s.run.initial.omega = {4e5, -3e5, 2e5};
    s.run.tol = job::min_tol;
    s.scene.auto_tolerance = false;
    setups.push_back({"a fast body at tol 1e-15", s});
  }
  {
    // A served job's speed is not the panel's to check: the budget holds it too.
    LiveSetup s = preset_setup(physics::Case::generic);
    s.speed = 1e300;
    setups.push_back({"speed 1e300", s});
  }
  for (const Costly& c : setups) {
    SCOPED_TRACE(c.what);
    LiveScene scene(c.setup);
    scene.set_playing(true);
    const auto start = std::chrono::steady_clock::now();
    int frames = 0;
    for (int frame = 0; frame < 12 && !scene.failure(); ++frame, ++frames) {
      const long before = scene.steps_taken();
      scene.update(0.1);
      EXPECT_LE(scene.steps_taken() - before,
                LiveScene::kFrameStepBudget + LiveScene::kSampleStepLimit)
          << "frame " << frame;
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %.1f ms a frame over %d frames%s\n", c.what, ms / std::max(1, frames), frames,
                scene.failure() ? (", then " + *scene.failure()).c_str() : "");
    // It says it cannot keep up, unless it stopped (then the report says why).
    if (!scene.failure()) {
      EXPECT_FALSE(scene.keeping_up()) << "pace " << scene.pace();
    }
  }
}

TEST(ClientValues, TheBudgetLeavesAnOrdinaryRunAtItsSpeed) {
  // The shipped presets at their speed, and at the fastest the panel allows.
  for (double speed : {4.0, kMaxSpeed}) {
    LiveSetup s = preset_setup(physics::Case::kovalevskaya);
    s.speed = speed;
    s.compared.push_back(nudged_by(1e-6));
    LiveScene scene(s);
    scene.set_playing(true);
    for (int frame = 0; frame < 60; ++frame) scene.update(1.0 / 30.0);
    ASSERT_FALSE(scene.failure()) << *scene.failure();
    EXPECT_TRUE(scene.keeping_up()) << "speed " << speed << ": pace " << scene.pace();
    EXPECT_NEAR(scene.time(), 2.0 * speed, 0.02 * speed);
  }
}

TEST(ClientValues, ThePanelSaysWhenTheRunIsBehind) {
  SessionOptions o = starting_with(physics::Case::generic);
  o.initial.compared.push_back(with_method(sim::Method::rk4, 1e-9, 0.0));
  SessionDriver d(o);
  EXPECT_FALSE(d.has_control("behind"));
  d.click("play");
  d.frames(10);
  EXPECT_TRUE(d.has_control("behind"));
}

}  // namespace
}  // namespace epviz::live::testing
