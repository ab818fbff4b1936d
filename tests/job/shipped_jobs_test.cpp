// The shipped jobs: listed by name from a data directory, sweeps left to
// `epviz sweep`, and a bare name given to `epviz render` found among them.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <fstream>

#include "io/bad_input.hpp"
#include "job/shipped_jobs.hpp"
#include "support/temp_dir.hpp"

namespace epviz::job {
namespace {

namespace fs = std::filesystem;

class ShippedJobs : public ::testing::Test {
 protected:
  test::TempDir dir_;
  void SetUp() override {
    write("single.json", R"({"simulation": {"case": "euler"}, "output": {"format": "mp4"}})");
    write("tiles.json", R"({"jobs": ["single.json"]})");
    write("figures.json", R"({"bench": {"quick": true}})");
    write("atlas.sweep.json", "not read: a sweep is epviz sweep's");
    write("top.section.json", "not read: a section is epviz section's");
    write("notes.txt", "not a job");
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
};

std::vector<std::string> names(const std::vector<ShippedJob>& jobs) {
  std::vector<std::string> out;
  for (const auto& j : jobs) out.push_back(j.name);
  return out;
}

TEST_F(ShippedJobs, AreTheRenderJobsOfTheDirectoryByNameWithoutSweeps) {
  const auto jobs = shipped_jobs(dir_.path());
  ASSERT_EQ(names(jobs), (std::vector<std::string>{"figures", "single", "tiles"}));
  EXPECT_EQ(jobs[0].about, "figures of epviz bench --quick");
  EXPECT_EQ(jobs[1].about, "render job: case euler, mp4");
  EXPECT_EQ(jobs[1].file, dir_ / "single.json");
  EXPECT_EQ(jobs[2].about, "gallery of 1 jobs");
}

TEST_F(ShippedJobs, TheListNamesTheDirectoryAndEachJobOnItsOwnLine) {
  const auto text = shipped_jobs_text(dir_.path());
  EXPECT_NE(text.find(dir_.path().string()), std::string::npos) << text;
  for (const auto& j : shipped_jobs(dir_.path()))
    EXPECT_NE(text.find("\n  " + j.name + " "), std::string::npos) << j.name << "\n" << text;
  // The directory; each command's heading and its files: three jobs, the
  // fixture's section and its sweep.
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + (1 + 3) + (1 + 1) + (1 + 1)) << text;
  EXPECT_NE(shipped_jobs_text({}).find("no shipped jobs"), std::string::npos);
}

TEST_F(ShippedJobs, EveryJobTheSourcesShipIsListed) {
  const fs::path dir = fs::path(EPVIZ_SOURCE_DIR) / "render_jobs";
  std::vector<std::string> expected;
  for (const auto& e : fs::directory_iterator(dir)) {
    const auto name = e.path().filename().string();
    if (e.path().extension() == ".json" && name.find(".sweep.") == std::string::npos &&
        name.find(".section.") == std::string::npos)
      expected.push_back(e.path().stem().string());
  }
  std::sort(expected.begin(), expected.end());
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(names(shipped_jobs(dir)), expected);
}

TEST_F(ShippedJobs, ABareNameIsTheShippedJobOfThatName) {
  EXPECT_EQ(job_file_named("single", dir_.path()), dir_ / "single.json");
  EXPECT_EQ(job_file_named("tiles.json", dir_.path()), dir_ / "tiles.json");
  // A path stays a path, found or not (reading it names it when it is missing).
  EXPECT_EQ(job_file_named("jobs/none.json", dir_.path()), fs::path("jobs/none.json"));
  for (const std::string name : {"atlas.sweep", "top.section", "notes", "none"}) {
    try {
      job_file_named(name, dir_.path());
      ADD_FAILURE() << name << ": accepted";
    } catch (const io::BadInput& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("'" + name + "': ", 0), 0u) << what;
      EXPECT_NE(what.find("--list-jobs"), std::string::npos) << what;
    }
  }
  EXPECT_THROW(job_file_named("single", {}), io::BadInput);
}

TEST_F(ShippedJobs, SectionsAndSweepsAreListedUnderTheirCommandsAndTakenByName) {
  write("level.section.json", R"({"case": "kovalevskaya"})");
  write("map.sweep.json", R"({"simulation": {"case": "generic"}})");
  const auto text = shipped_jobs_text(dir_.path());
  const auto render = text.find("epviz render NAME:\n");
  const auto section = text.find("epviz section NAME:\n");
  const auto sweep = text.find("epviz sweep NAME:\n");
  ASSERT_NE(render, std::string::npos) << text;
  ASSERT_NE(section, std::string::npos) << text;
  ASSERT_NE(sweep, std::string::npos) << text;
  EXPECT_LT(render, section);
  EXPECT_LT(section, sweep);
  EXPECT_NE(text.find("  level  ", section), std::string::npos) << text;
  EXPECT_NE(text.find("Poincare section: case kovalevskaya"), std::string::npos) << text;
  EXPECT_NE(text.find("parameter sweep: case generic"), std::string::npos) << text;
  // The fixture's unreadable ones are listed, saying so, not dropped.
  EXPECT_NE(text.find("  top  "), std::string::npos) << text;
  EXPECT_EQ(names(shipped_files(dir_.path(), ShippedKind::sweep)),
            (std::vector<std::string>{"atlas", "map"}));

  EXPECT_EQ(job_file_named("level", dir_.path(), ShippedKind::section),
            dir_ / "level.section.json");
  EXPECT_EQ(job_file_named("level.section.json", dir_.path(), ShippedKind::section),
            dir_ / "level.section.json");
  EXPECT_EQ(job_file_named("map", dir_.path(), ShippedKind::sweep), dir_ / "map.sweep.json");
  // Each command takes only its own kind.
  EXPECT_THROW(job_file_named("single", dir_.path(), ShippedKind::section), io::BadInput);
  EXPECT_THROW(job_file_named("level", dir_.path(), ShippedKind::sweep), io::BadInput);
  EXPECT_THROW(job_file_named("level", dir_.path(), ShippedKind::render), io::BadInput);
  try {
    job_file_named("nope", dir_.path(), ShippedKind::section);
    ADD_FAILURE() << "a name that is nothing was taken";
  } catch (const io::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("no such section file, nor a shipped section"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(ShippedJobs, TheirDirectoryFollowsTheDataSearchPath) {
  fs::create_directories(dir_ / "data" / "render_jobs");
  ::setenv("EPVIZ_DATA_DIR", (dir_ / "data").c_str(), 1);
  const auto found = shipped_jobs_dir();
  ::unsetenv("EPVIZ_DATA_DIR");
  EXPECT_EQ(found, dir_ / "data" / "render_jobs");
  EXPECT_EQ(shipped_jobs_dir(), fs::path(EPVIZ_SOURCE_DIR) / "render_jobs");
}

}  // namespace
}  // namespace epviz::job
