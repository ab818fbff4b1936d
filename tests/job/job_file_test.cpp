// Job files as `epviz render` takes them: a single job, a gallery of jobs or
// the bench's figures, each read strictly through its declared keys.
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "io/bad_input.hpp"
#include "job/job_file.hpp"

namespace epviz::job {
namespace {

namespace fs = std::filesystem;

class JobFile : public ::testing::Test {
 protected:
  fs::path dir_ = fs::temp_directory_path() / ("epviz-job-file-" + std::to_string(::getpid()));
  void SetUp() override {
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "jobs");
    write("jobs/euler.json", R"({"simulation": {"case": "euler"}})");
    write("jobs/clip.json", R"({"simulation": {"case": "lagrange"}, "output": {"format": "mp4"}})");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  std::string refusal(const std::string& text) {
    try {
      load_job_file(write("bad.json", text));
    } catch (const io::BadInput& e) {
      return e.what();
    }
    return "no refusal";
  }
};

TEST_F(JobFile, ASingleJobGetsItsOutputNameFromItsFormat) {
  const auto still = load_job_file(dir_ / "jobs/euler.json");
  ASSERT_TRUE(still.single);
  EXPECT_FALSE(still.gallery || still.bench);
  EXPECT_EQ(still.single->output.name, "frame");
  EXPECT_EQ(still.single->file, dir_ / "jobs/euler.json");
  EXPECT_EQ(*still.single->simulation.case_name, "euler");
  EXPECT_EQ(load_job_file(dir_ / "jobs/clip.json").single->output.name, "clip");
}

TEST_F(JobFile, AGalleryReadsItsJobsBesideItself) {
  const auto loaded = load_job_file(write("jobs/g.json", R"({"jobs": ["euler.json", "clip.json"],
      "tile": {"width": 320, "columns": 2, "at": 0.25}, "videos": "webm", "dir": "figs"})"));
  ASSERT_TRUE(loaded.gallery);
  const auto& g = *loaded.gallery;
  ASSERT_EQ(g.jobs.size(), 2u);
  EXPECT_EQ(g.jobs[1].file, dir_ / "jobs/clip.json");
  EXPECT_EQ(g.jobs[1].output.name, "clip");
  EXPECT_EQ(g.tile_width, 320);
  EXPECT_EQ(g.tile_height, 360);  // not given: the default
  EXPECT_EQ(g.columns, 2);
  EXPECT_EQ(g.at, 0.25);
  EXPECT_EQ(g.videos, io::VideoFormat::webm);
  EXPECT_EQ(g.dir, "figs");
  EXPECT_FALSE(g.grid_video);
}

TEST_F(JobFile, GalleryMistakesNameTheFileAndKey) {
  EXPECT_NE(refusal(R"({"jobs": []})").find("bad.json: key 'jobs': expected a non-empty array"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"jobs": ["jobs/euler.json", 3]})").find("item 1: expected a job file name"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"jobs": ["jobs/euler.json"], "tile": {"widht": 3}})").find("tile.widht"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"jobs": ["jobs/euler.json"], "tile": {"at": 1.5}})").find("tile.at"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"jobs": ["jobs/euler.json"], "videos": "avi"})").find("videos"),
            std::string::npos);
  // A job of the gallery is read as a single job: its mistakes name its own file.
  write("jobs/broken.json", R"({"simulation": {"case": "euler"}, "widht": 320})");
  EXPECT_NE(refusal(R"({"jobs": ["jobs/broken.json"]})").find("broken.json: key 'widht'"),
            std::string::npos);
}

TEST_F(JobFile, BenchFiguresTakeTheStudysCasesAndADirectory) {
  const auto loaded = load_job_file(
      write("b.json", R"({"bench": {"quick": true, "cases": ["euler", "lagrange"]}})"));
  ASSERT_TRUE(loaded.bench);
  EXPECT_TRUE(loaded.bench->quick);
  EXPECT_EQ(loaded.bench->cases, (std::vector<std::string>{"euler", "lagrange"}));
  EXPECT_EQ(loaded.bench->dir, "out/bench");
  EXPECT_NE(refusal(R"({"bench": {"cases": "euler"}})").find("bench.cases"), std::string::npos);
  EXPECT_NE(refusal(R"({"bench": {}, "jobs": []})").find("'jobs'"), std::string::npos);
}

TEST_F(JobFile, TheKeysOfEachFormatAreListedForTheDocumentation) {
  auto has = [](const std::vector<KeyInfo>& keys, const std::string& path) {
    return std::any_of(keys.begin(), keys.end(), [&](const KeyInfo& k) { return k.path == path; });
  };
  const auto gallery = gallery_job_keys();
  for (const char* key : {"jobs", "tile", "tile.width", "tile.at", "videos", "grid_video", "dir"})
    EXPECT_TRUE(has(gallery, key)) << key;
  const auto bench = bench_job_keys();
  for (const char* key : {"bench", "bench.quick", "bench.cases", "dir"})
    EXPECT_TRUE(has(bench, key)) << key;
}

}  // namespace
}  // namespace epviz::job
