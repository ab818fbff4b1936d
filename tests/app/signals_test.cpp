// Temporaries do not outlive a run: SIGTERM/SIGINT remove them, and a later
// run into the same directory removes those of processes that no longer exist
// (SIGKILL cannot be caught).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <thread>

#include "io/temp_name.hpp"
#include "support/cli.hpp"
#include "support/dead_pid.hpp"
#include "support/eventually.hpp"
#include "support/render_job.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

using test::dead_pid;

std::vector<std::string> temporaries_in(const fs::path& dir) {
  std::vector<std::string> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (io::parse_temporary_name(e.path().filename().string()))
      found.push_back(e.path().filename().string());
  return found;
}

nlohmann::json video_job(const fs::path& out, double seconds) {
  auto j = test::small_render_job(out, 30, seconds);
  j["output"]["format"] = "mp4";
  j["output"]["name"] = "clip";
  return j;
}

pid_t start_epviz(const std::vector<std::string>& args) {
  const pid_t child = ::fork();
  if (child == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    std::vector<char*> argv{const_cast<char*>(EPVIZ_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(EPVIZ_BINARY, argv.data());
    ::_exit(127);
  }
  return child;
}

void expect_signal_cleans_up_video(int sig) {
  test::TempDir dir;
  const auto out = dir / "video";
  std::ofstream(dir / "job.json") << video_job(out, 60.0).dump();
  const pid_t child = start_epviz({"render", (dir / "job.json").string()});
  ASSERT_GT(child, 0);
  // Mid-way through the frames: ffmpeg has written encoded ones to the temporary.
  const auto temporary = out / ("clip.mp4" + io::temporary_suffix(child));
  const bool writing = test::eventually(
      [&] {
        std::error_code ec;
        const auto size = fs::file_size(temporary, ec);
        return !ec && size > 0;
      },
      std::chrono::seconds(60));
  if (!writing) ::kill(child, SIGKILL);
  ::kill(child, sig);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(writing) << "the render never wrote to " << temporary;
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "status " << status;
  // The handler removed the temporary before the process ended.
  EXPECT_TRUE(temporaries_in(out).empty()) << temporaries_in(out).front();
  EXPECT_FALSE(fs::exists(out / "clip.mp4")) << "a partial video under the real name";
}

TEST(Signals, SigtermDuringVideoRenderLeavesNoTemporary) { expect_signal_cleans_up_video(SIGTERM); }
TEST(Signals, SigintDuringVideoRenderLeavesNoTemporary) { expect_signal_cleans_up_video(SIGINT); }

TEST(Signals, RenderRemovesStaleTemporariesOfDeadProcesses) {
  test::TempDir dir;
  const auto out = dir / "frames";
  fs::create_directories(out);
  const auto stale = out / ("x.mp4" + io::temporary_suffix(dead_pid()));
  const auto live = out / ("y.mp4" + io::temporary_suffix(::getpid()));  // this test is alive
  std::ofstream(stale) << "left by a killed run";
  std::ofstream(live) << "being written";
  const auto j = test::small_render_job(out, 2, 1.0);
  std::ofstream(dir / "job.json") << j.dump();
  const auto r = test::run_epviz("render " + (dir / "job.json").string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(stale)) << "stale temporary of a dead process kept";
  EXPECT_TRUE(fs::exists(live)) << "temporary of a live process removed";
}

TEST(Signals, SimulateRemovesStaleTemporariesBesideItsOutputs) {
  test::TempDir dir;
  const auto stale = dir / ("s.csv" + io::temporary_suffix(dead_pid()));
  std::ofstream(stale) << "left by a killed run";
  const auto r =
      test::run_epviz("simulate --case euler --samples 5 --csv " + (dir / "s.csv").string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(dir / "s.csv"));
}

// A section killed with SIGKILL while writing leaves its temporaries; the
// next run removes them beside each of its outputs, as simulate does.
TEST(Signals, SectionRemovesStaleTemporariesBesideItsOutputs) {
  test::TempDir dir;
  fs::create_directories(dir / "pictures");
  const auto stale_csv = dir / ("c.csv" + io::temporary_suffix(dead_pid()));
  const auto stale_svg = dir / "pictures" / ("c.svg" + io::temporary_suffix(dead_pid()));
  const auto live = dir / ("d.csv" + io::temporary_suffix(::getpid()));  // this test is alive
  for (const auto& f : {stale_csv, stale_svg, live}) std::ofstream(f) << "being written";
  const nlohmann::json section = {{"case", "generic"},
                                  {"level", {{"energy", 2}, {"area", 1}}},
                                  {"orbits", 1},
                                  {"crossings", 3},
                                  {"csv", (dir / "c.csv").string()},
                                  {"svg", (dir / "pictures" / "c.svg").string()}};
  std::ofstream(dir / "s.section.json") << section.dump();
  const auto r = test::run_epviz("section " + (dir / "s.section.json").string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(stale_csv)) << "stale temporary beside the CSV kept";
  EXPECT_FALSE(fs::exists(stale_svg)) << "stale temporary beside the SVG kept";
  EXPECT_TRUE(fs::exists(live)) << "temporary of a live process removed";
}

}  // namespace
}  // namespace epviz
