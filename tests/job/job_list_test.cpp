// The jobs a list of paths names (`epviz check JOB...`): files, galleries and
// directories, each job once.
#include <gtest/gtest.h>

#include <fstream>

#include "io/bad_input.hpp"
#include "job/job_list.hpp"
#include "support/temp_dir.hpp"

namespace epviz::job {
namespace {

namespace fs = std::filesystem;

class JobList : public ::testing::Test {
 protected:
  test::TempDir dir_;
  void write(const std::string& name, const std::string& text) {
    fs::create_directories((dir_ / name).parent_path());
    std::ofstream(dir_ / name) << text;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
};

TEST_F(JobList, ADirectoryGivesItsJobsInNameOrderWithoutBenchSweepOrSectionFiles) {
  write("jobs/b.json", R"({"simulation": {"case": "euler"}})");
  write("jobs/a.json", R"({"simulation": {"case": "lagrange"}})");
  write("jobs/bench.json", R"({"bench": {}})");
  // Files of other commands sit beside render jobs (render_jobs/ ships both);
  // read as render jobs they would be refused for their keys.
  write("jobs/chaos.sweep.json", R"({"simulation": {"case": "generic"}, "axes": []})");
  write("jobs/k.section.json", R"({"case": "kovalevskaya", "section": {}})");
  write("jobs/notes.txt", "not a job");
  const auto jobs = render_jobs_in({path("jobs")});
  ASSERT_EQ(jobs.size(), 2u);
  EXPECT_EQ(jobs[0].first.file.filename(), "a.json");
  EXPECT_EQ(jobs[1].first.file.filename(), "b.json");
  EXPECT_EQ(*jobs[0].first.simulation.case_name, "lagrange");
}

TEST_F(JobList, AGalleryGivesItsJobsShownByTheirOwnFiles) {
  write("g/euler.json", R"({"simulation": {"case": "euler"}})");
  write("g/hess.json", R"({"simulation": {"case": "hess"}})");
  write("g/gallery.json", R"({"jobs": ["euler.json", "hess.json"]})");
  const auto jobs = render_jobs_in({path("g/gallery.json")});
  ASSERT_EQ(jobs.size(), 2u);
  EXPECT_EQ(jobs[1].second, (dir_ / "g/hess.json").string());
}

TEST_F(JobList, AJobNamedTwiceIsCheckedOnceUnderItsFirstName) {
  write("g/euler.json", R"({"simulation": {"case": "euler"}})");
  write("g/gallery.json", R"({"jobs": ["euler.json"]})");
  const auto jobs = render_jobs_in({path("g/euler.json"), path("g/gallery.json"), path("g")});
  ASSERT_EQ(jobs.size(), 1u);
  EXPECT_EQ(jobs[0].second, path("g/euler.json"));
}

TEST_F(JobList, RefusesABenchJobNamedDirectlyAndAnEmptyDirectory) {
  write("bench.json", R"({"bench": {}})");
  fs::create_directories(dir_ / "empty");
  EXPECT_THROW(render_jobs_in({path("bench.json")}), io::BadInput);
  try {
    render_jobs_in({path("empty")});
    ADD_FAILURE() << "an empty directory was accepted";
  } catch (const io::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("no render jobs (*.json)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace epviz::job

namespace epviz::job {
namespace {

// docs/ci.md's recipes run `epviz check render_jobs/`: the shipped directory,
// sweeps and sections beside the render jobs, must read as a list of jobs.
TEST(ShippedJobList, TheShippedDirectoryReadsAsRenderJobs) {
  const auto dir = std::filesystem::path(EPVIZ_SOURCE_DIR) / "render_jobs";
  const auto jobs = render_jobs_in({dir.string()});
  EXPECT_GE(jobs.size(), 6u);
  for (const auto& [job, shown] : jobs) EXPECT_FALSE(is_other_command_file(job.file)) << shown;
}

}  // namespace
}  // namespace epviz::job
