// Replays a session recorded in headless Chromium by tests/e2e/record.mjs
// (`epviz serve --record` with render_jobs/hess.json): click the case combo,
// pick Kovalevskaya, drag the I3 slider, press Play. No browser, no server:
// the recorded page messages go straight into a session.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "live/replay.hpp"
#include "physics/cases.hpp"
#include "session_driver.hpp"

namespace epviz::live {
namespace {

const std::string kSource = EPVIZ_SOURCE_DIR;

// The setup `epviz serve render_jobs/hess.json` starts from (the panel's
// layout depends on its title, so the recording's clicks land where they did).
LiveSetup hess_job_setup() {
  std::ifstream in(kSource + "/render_jobs/hess.json");
  const auto job = nlohmann::json::parse(in);
  LiveSetup s = preset_setup(physics::Case::hess);
  s.scene.title = job["title"];
  s.scene.trail_length = job["trail"]["length"];
  s.speed = double(job["simulation"]["t_end"]) / double(job["duration"]);
  return s;
}

TEST(Replay, ARecordedBrowserSessionPicksTheCaseEditsTheBodyAndPlays) {
  SessionOptions o;
  o.initial = hess_job_setup();
  o.fixed_clock = true;  // the same frames on every machine; the server's font (not the bitmap one)
  LiveSession session(testing::shared_gl(), o);

  std::ifstream recording(kSource + "/tests/live/recordings/pick_case_drag_play.jsonl");
  ASSERT_TRUE(recording) << "missing recording";
  // The first frame, before any input: the Hess top at rest.
  std::stringstream head;
  std::string line;
  std::getline(recording, line);  // resize
  head << line << "\n"
       << R"({"type":"render"})"
       << "\n";
  replay(session, head);
  const auto first = testing::image_hash(session.render());
  const auto view = session.view_3d();

  const ReplayCounts n = replay(session, recording);
  EXPECT_GT(n.messages, 10);
  EXPECT_GT(n.frames, 20);

  const auto& setup = session.scene().setup();
  EXPECT_EQ(setup.run.case_id, physics::Case::kovalevskaya) << "the combo pick did not land";
  const double I3 = setup.run.body.inertia.z();
  EXPECT_GT(I3, physics::preset(physics::Case::kovalevskaya).body.inertia.z() + 0.2)
      << "the slider drag did not land";
  EXPECT_FALSE(
      physics::broken_condition(physics::Case::kovalevskaya, setup.run.body, setup.run.initial));
  EXPECT_TRUE(session.scene().playing()) << "Play did not land";
  EXPECT_GT(session.scene().time(), 0.0);

  // The picture follows: the body box is the new one, and it moves.
  const auto& image = session.render();
  EXPECT_NE(testing::image_hash(image), first);
  EXPECT_EQ(session.view_3d().width, view.width);
  const auto a = testing::image_hash(session.render());
  const auto b = testing::image_hash(session.render());
  EXPECT_NE(a, b) << "playing, yet two frames are the same";
}

TEST(Replay, ALineThatIsNotAPageMessageIsReportedWithItsNumber) {
  SessionOptions o;
  o.fixed_clock = true;
  o.builtin_font = true;
  LiveSession session(testing::shared_gl(), o);
  std::stringstream bad(R"({"type":"resize","width":320,"height":200})"
                        "\n"
                        R"({"type":"jump"})"
                        "\n");
  try {
    replay(session, bad);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace epviz::live
