// check::run_checks, the whole of `epviz check` after its options, driven by
// frame sources that hand out test images instead of drawing with GL: the
// exit codes (a failed frame, a check that cannot be done), output in job
// order for any number of workers, the JUnit file's times and attachments.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "check/check_run.hpp"
#include "io/bad_input.hpp"
#include "support/temp_dir.hpp"
#include "test_images.hpp"

namespace epviz::check {
namespace {

namespace fs = std::filesystem;

// Job k's frames are discs, or flat images from frame `changed_from` on, each
// handed out once `spin` of steady time has passed since the last (a
// stand-in for drawing, so that times per frame are known to be at least it).
class FakeFrames : public FrameSource {
 public:
  FakeFrames(int changed_from, std::chrono::milliseconds spin)
      : changed_from_(changed_from), spin_(spin) {}
  const RenderEnvironment& environment() const override { return environment_; }
  std::optional<std::string> draw(std::size_t, const GoldenJob& job,
                                  const std::function<void(const ImageView&)>& on_frame) override {
    for (const int f : job.frames) {
      const auto until = std::chrono::steady_clock::now() + spin_;
      while (std::chrono::steady_clock::now() < until) {
      }
      const auto image = f >= changed_from_ ? flat_image(job.width, job.height, 9, 9, 9)
                                            : disc_image(job.width, job.height);
      on_frame(image.view());
    }
    return std::nullopt;
  }

 private:
  RenderEnvironment environment_{"fake GL", "1.0", "builtin", ""};
  int changed_from_;
  std::chrono::milliseconds spin_;
};

class CheckRun : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* name : {"a", "b", "c", "d"}) {
      const auto file = dir_ / (std::string(name) + ".json");
      std::ofstream(file) << "{\"job\": \"" << name << "\"}\n";
      jobs_.push_back(golden_job("jobs/" + std::string(name) + ".json", file, dir_ / "golden", 10,
                                 24, 16, {}, false));
    }
    settings_.update_command = [](const GoldenJob& job, const std::vector<int>&) {
      return "update " + job.shown;
    };
  }
  int run(int changed_from, RunSettings s, std::chrono::milliseconds spin = {}) {
    out_.str("");
    err_.str("");
    return run_checks(
        jobs_, s, [&] { return std::make_unique<FakeFrames>(changed_from, spin); }, out_, err_);
  }
  int update() {
    auto s = settings_;
    s.update = true;
    return run(100, s);
  }

  test::TempDir dir_;
  std::vector<GoldenJob> jobs_;
  RunSettings settings_;
  std::ostringstream out_, err_;
};

TEST_F(CheckRun, ExitCodesSayPassedOrAFrameFailed) {
  ASSERT_EQ(update(), kExitPassed) << out_.str() << err_.str();
  EXPECT_NE(out_.str().find("12 goldens written"), std::string::npos) << out_.str();
  EXPECT_EQ(run(100, settings_), kExitPassed) << out_.str();
  EXPECT_NE(out_.str().find("12 passed, 0 failed"), std::string::npos) << out_.str();
  EXPECT_EQ(run(9, settings_), kExitFrameFailed);  // the last frame of each job
  EXPECT_NE(out_.str().find("8 passed, 4 failed"), std::string::npos) << out_.str();
  EXPECT_EQ(err_.str(), "");
}

TEST_F(CheckRun, NothingToDrawWithIsNotAFailedFrame) {
  const auto status = run_checks(
      jobs_, settings_,
      []() -> std::unique_ptr<FrameSource> {
        throw std::runtime_error("no GL here: install libegl-mesa0");
      },
      out_, err_);
  EXPECT_EQ(status, kExitCannotCheck);
  EXPECT_EQ(err_.str(), "epviz: error: no GL here: install libegl-mesa0\n");
  EXPECT_EQ(out_.str(), "");
}

TEST_F(CheckRun, AFileThatCannotBeWrittenIsNotAFailedFrame) {
  ASSERT_EQ(update(), kExitPassed);
  auto s = settings_;
  s.junit = "/proc/epviz-no-such-dir/check.xml";
  EXPECT_EQ(run(100, s), kExitCannotCheck);
  const std::string err = err_.str();
  EXPECT_NE(err.find("/proc/epviz-no-such-dir/check.xml"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_EQ(err.rfind("epviz: error: ", 0), 0u) << err;
}

TEST_F(CheckRun, BadInputIsPassedOnForExitCodeTwo) {
  ASSERT_EQ(update(), kExitPassed);
  std::ofstream(jobs_[2].golden_dir / "golden.json") << "[]";
  EXPECT_THROW(run(100, settings_), io::BadInput);
}

TEST_F(CheckRun, AnyNumberOfWorkersPrintsTheSameInJobOrder) {
  ASSERT_EQ(update(), kExitPassed);
  auto s = settings_;
  EXPECT_EQ(run(5, s), kExitFrameFailed);
  const std::string one = out_.str();
  s.workers = 3;
  EXPECT_EQ(run(5, s), kExitFrameFailed);
  EXPECT_EQ(out_.str(), one);
  std::size_t at = 0;
  for (const char* job : {"a", "b", "c", "d"}) {
    const auto next = one.find(std::string("jobs/") + job + ".json frame 0:");
    ASSERT_NE(next, std::string::npos) << one;
    EXPECT_GE(next, at) << one;
    at = next;
  }
}

// JUnit: every frame's time (at least the spin its drawing took), the suite's
// time their sum, and the report's images of failing frames as attachments.
TEST_F(CheckRun, JunitHasTimesPerFrameAndAttachesTheReportImages) {
  ASSERT_EQ(update(), kExitPassed);
  auto s = settings_;
  s.report_dir = dir_ / "report";
  s.junit = dir_ / "check.xml";
  fs::create_directories(s.report_dir);
  EXPECT_EQ(run(9, s, std::chrono::milliseconds(5)), kExitFrameFailed);
  const auto xml = test::slurp(s.junit);
  const std::regex testcase("<testcase [^>]* time=\"([0-9.]+)\">");
  int cases = 0;
  for (std::sregex_iterator it(xml.begin(), xml.end(), testcase), end; it != end; ++it, ++cases)
    EXPECT_GE(std::stod((*it)[1]), 0.005) << (*it)[0];
  EXPECT_EQ(cases, 12);
  const std::regex attachment(R"(\[\[ATTACHMENT\|([^\]]+)\]\])");
  int attachments = 0;
  for (std::sregex_iterator it(xml.begin(), xml.end(), attachment), end; it != end;
       ++it, ++attachments)
    EXPECT_TRUE(fs::is_regular_file(std::string((*it)[1]))) << (*it)[1];
  EXPECT_EQ(attachments, 4 * 3);  // golden, actual and diff of each job's last frame
}

}  // namespace
}  // namespace epviz::check
