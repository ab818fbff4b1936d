// `epviz check` through the real binary: goldens it just wrote pass, changes
// a person would notice fail (with a diff image, an HTML report naming the
// frame and JUnit XML counting the failures), a missing golden names the
// command that creates it, and bad input exits 2 with one line.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "io/png_reader.hpp"
#include "support/cli.hpp"
#include "support/peak_rss.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

// render_jobs/kovalevskaya.json at 160x120 (270 frames; checked: 0, 134, 269).
nlohmann::json small_job() {
  std::ifstream in(fs::path(EPVIZ_SOURCE_DIR) / "render_jobs" / "kovalevskaya.json");
  auto j = nlohmann::json::parse(in);
  j["width"] = 160;
  j["height"] = 120;
  return j;
}

fs::path write_job(const fs::path& file, const nlohmann::json& j) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << j.dump(2);
  return file;
}

std::size_t count_lines_starting(const std::string& text, const std::string& prefix) {
  std::size_t n = 0;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0;
  return n;
}

// Parses JUnit XML with Python's XML parser (an independent reader): the
// counts of <testcase> and <failure> elements and the root's tests/failures
// attributes, or "" when the file is not well-formed XML.
std::string junit_counts(const fs::path& file) {
  const std::string cmd =
      "/usr/bin/python3 -c \"import sys, xml.etree.ElementTree as E; r = "
      "E.parse(sys.argv[1]).getroot(); "
      "print(r.tag, len(r.findall('.//testcase')), len(r.findall('.//failure')), r.get('tests'), "
      "r.get('failures'))\" " +
      file.string() + " 2>/dev/null";
  std::string out;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[256];
    while (fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  return out;
}

class Check : public ::testing::Test {
 protected:
  void SetUp() override { job_ = write_job(dir_ / "jobs" / "kov.json", small_job()); }
  test::CliResult epviz(const std::string& args) { return test::run_epviz(args, dir_); }
  std::string job() const { return job_.string(); }
  fs::path golden(int frame) const {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    return dir_ / "jobs" / "golden" / "kov" / name;
  }

  test::TempDir dir_;
  fs::path job_;
};

TEST_F(Check, PassesAgainstGoldensItJustWrote) {
  const auto u = epviz("check " + job() + " --update");
  ASSERT_EQ(u.exit_code, 0) << u.out << u.err;
  for (int f : {0, 134, 269}) {
    const auto png = io::read_png_rgba(golden(f));
    ASSERT_TRUE(png) << golden(f);
    EXPECT_EQ(png->width, 160);
    EXPECT_EQ(png->height, 120);
  }
  const auto rec = nlohmann::json::parse(test::slurp(golden(0).parent_path() / "golden.json"));
  EXPECT_EQ(rec["frames"], nlohmann::json({0, 134, 269}));
  EXPECT_EQ(rec["width"], 160);
  EXPECT_FALSE(rec["gl_renderer"].get<std::string>().empty());
  EXPECT_FALSE(rec["gl_version"].get<std::string>().empty());
  EXPECT_EQ(rec["epviz_version"].get<std::string>().empty(), false);
  EXPECT_EQ(rec["job_hash"].get<std::string>().rfind("fnv1a64:", 0), 0u);
  // The font the text was drawn with, and its bytes' hash.
  EXPECT_TRUE(fs::is_regular_file(rec["font_file"].get<std::string>())) << rec.dump();
  EXPECT_EQ(rec["font_hash"].get<std::string>().rfind("fnv1a64:", 0), 0u);

  // The largest SSIM threshold too: frames equal to their goldens have SSIM exactly 1.
  for (const char* metric : {"pixel", "ssim", "ssim --threshold 1"}) {
    const auto r = epviz(std::string("check ") + job() + " --metric " + metric);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(count_lines_starting(r.out, "PASS " + job() + " frame "), 3u) << r.out;
    EXPECT_NE(r.out.find("3 passed, 0 failed"), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "");
  }
  // In memory: nothing but the goldens was written next to the job.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "jobs"), {}), 2);
}

// Frames are checked as they are drawn and let go: a check of 100 frames
// peaks at about the memory of a check of 5, for --update (which keeps PNGs
// only) and for the comparison alike.
TEST_F(Check, MemoryDoesNotGrowWithTheFramesChecked) {
  auto j = small_job();
  j["width"] = 320;
  j["height"] = 240;
  const std::string file = write_job(dir_ / "jobs" / "mem.json", j).string();
  const auto peak = [&](const std::string& frames, bool update) {
    std::vector<std::string> args{"check", file, "--frames", frames};
    if (update) args.push_back("--update");
    return test::peak_rss_kb(args, dir_.path().string());
  };
  const long few_update = peak("0:4", true), many_update = peak("0:99", true);
  const long few = peak("0:4", false), many = peak("0:99", false);
  for (long kb : {few_update, many_update, few, many}) ASSERT_GT(kb, 0);
  // Kept in memory, 100 frames of 320x240 would take 30 MB more.
  EXPECT_LT(many_update - few_update, 12 * 1024)
      << "--update peak " << few_update << " kB for 5 frames, " << many_update << " for 100";
  EXPECT_LT(many - few, 12 * 1024)
      << "check peak " << few << " kB for 5 frames, " << many << " for 100";
}

TEST_F(Check, HelpStatesTheDefaultsOfDocsCiMd) {
  // docs/ci.md, "Metrics and tolerances" (tests/check/defaults_test.cpp holds
  // the docs to the numbers in check/tolerance.hpp).
  const auto r = epviz("check --help");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* stated :
       {"equal (default 1);", "lowest SSIM that passes (default 0.999)", "differ (default 0.5)"})
    EXPECT_NE(r.out.find(stated), std::string::npos) << stated << " in\n" << r.out;
}

struct Change {
  std::string name;
  std::function<void(nlohmann::json&)> edit;
};
void PrintTo(const Change& c, std::ostream* os) { *os << c.name; }

class CheckNoticeable : public Check, public ::testing::WithParamInterface<Change> {};

TEST_P(CheckNoticeable, ChangeFailsWithDiffReportAndJunit) {
  ASSERT_EQ(epviz("check " + job() + " --update").exit_code, 0);
  auto j = small_job();
  GetParam().edit(j);
  write_job(job_, j);
  const auto rep = dir_ / "report", xml = dir_ / "junit.xml";
  const auto r = epviz("check " + job() + " --report " + rep.string() + " --junit " + xml.string());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto failed = count_lines_starting(r.out, "FAIL " + job() + " frame ");
  EXPECT_GE(failed, 1u) << r.out;
  EXPECT_NE(
      r.out.find(std::to_string(3 - failed) + " passed, " + std::to_string(failed) + " failed"),
      std::string::npos)
      << r.out;

  // Every failing frame: named in the report, with golden, actual and diff images.
  const auto html = test::slurp(rep / "index.html");
  const std::regex fail_line(
      "FAIL " + std::regex_replace(job(), std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
      " frame ([0-9]+):");
  std::size_t seen = 0;
  for (std::sregex_iterator it(r.out.begin(), r.out.end(), fail_line), end; it != end;
       ++it, ++seen) {
    const std::string frame = (*it)[1];
    EXPECT_NE(html.find(job() + " frame " + frame + "</h2>"), std::string::npos)
        << "frame " << frame;
    char stem[64];
    std::snprintf(stem, sizeof stem, "1_kov_frame_%04d", std::stoi(frame));
    for (const char* kind : {"golden", "actual", "diff"}) {
      const auto png = io::read_png_rgba(rep / (std::string(stem) + "." + kind + ".png"));
      ASSERT_TRUE(png) << stem << " " << kind;
      EXPECT_EQ(png->width, 160);
    }
    EXPECT_NE(html.find(std::string(stem) + ".diff.png"), std::string::npos);
  }
  EXPECT_EQ(seen, failed);
  // Every change here is to the job file: its own verdict, not "rendering changed".
  EXPECT_EQ(count_lines_starting(r.out, "FAIL "), failed);
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("FAIL ", 0) != 0) continue;
    EXPECT_NE(line.find("; job changed since goldens: update or revert (update: epviz check "),
              std::string::npos)
        << line;
  }

  const std::string n = std::to_string(failed);
  EXPECT_EQ(junit_counts(xml), "testsuites 3 " + n + " 3 " + n + "\n") << test::slurp(xml);
}

INSTANTIATE_TEST_SUITE_P(
    Changes, CheckNoticeable,
    ::testing::Values(Change{"camera_moved_2_degrees",
                             [](auto& j) {
                               j["camera"] = {{"azimuth", 37.0}};
                             }},
                      Change{"body_colour",
                             [](auto& j) {
                               j["colours"] = {{"body", "#c09050"}};
                             }},
                      Change{"one_more_second_of_trail",
                             [](auto& j) { j["trail"]["length"] = 21.0; }},
                      Change{"another_method", [](auto& j) { j["simulation"]["method"] = "rk4"; }}),
    [](const auto& param_info) { return param_info.param.name; });

TEST_F(Check, MissingGoldenFailsWithTheCommandThatCreatesIt) {
  const auto r = epviz("check " + job() + " --frames 3,7:8");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(count_lines_starting(r.out, "FAIL " + job() + " frame "), 3u) << r.out;
  const std::string cmd = "epviz check " + job() + " --frames 3,7,8 --update";
  const auto at = r.out.find("create it with: " + cmd + "\n");
  ASSERT_NE(at, std::string::npos) << r.out;
  // The command it names creates exactly those goldens, after which the check passes.
  EXPECT_EQ(epviz(cmd.substr(std::string("epviz ").size())).exit_code, 0);
  EXPECT_TRUE(fs::exists(golden(7)));
  const auto again = epviz("check " + job() + " --frames 3,7:8");
  EXPECT_EQ(again.exit_code, 0) << again.out;
  EXPECT_NE(again.out.find("3 passed, 0 failed"), std::string::npos);
}

TEST_F(Check, WarnsOnceWhenTheGoldensCameFromAnotherRenderer) {
  ASSERT_EQ(epviz("check " + job() + " --frames 0 --update").exit_code, 0);
  const auto record = golden(0).parent_path() / "golden.json";
  auto rec = nlohmann::json::parse(test::slurp(record));
  rec["gl_renderer"] = "SomeGPU 9000";
  std::ofstream(record) << rec.dump(2);
  const auto r = epviz("check " + job() + " --frames 0");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("SomeGPU 9000"), std::string::npos) << r.err;
}

// Exit 1 is kept for frames that fail: a check that cannot be done here
// (no font, a file it cannot write) exits 5 with one line naming the cause.
TEST_F(Check, WhatStopsTheCheckIsNotAFailedFrame) {
  ASSERT_EQ(epviz("check " + job() + " --frames 0 --update").exit_code, 0);
  const std::string font = (dir_ / "no-such-font.ttf").string();
  const auto no_font =
      test::run_epviz("check " + job() + " --frames 0", dir_, "env EPVIZ_FONT=" + font);
  EXPECT_EQ(no_font.exit_code, 5) << no_font.out << no_font.err;
  EXPECT_EQ(no_font.err, "epviz: error: cannot load the font '" + font +
                             "' for the text in pictures (a TTF or OTF file)\n");
  const auto junit = epviz("check " + job() + " --frames 0 --junit /proc/epviz-check.xml");
  EXPECT_EQ(junit.exit_code, 5) << junit.out << junit.err;
  EXPECT_EQ(std::count(junit.err.begin(), junit.err.end(), '\n'), 1) << junit.err;
  EXPECT_NE(junit.err.find("/proc/epviz-check.xml"), std::string::npos) << junit.err;
  EXPECT_EQ(junit.err.find("filesystem error"), std::string::npos) << junit.err;
}

TEST_F(Check, ParallelJobsGiveTheSameOutputInTheSameOrder) {
  // A directory of jobs of different sizes (and a gallery listing two of them).
  auto b = small_job(), c = small_job();
  b["width"] = 200;
  b["height"] = 100;
  c["simulation"]["case"] = "lagrange";
  write_job(dir_ / "jobs" / "b.json", b);
  write_job(dir_ / "jobs" / "c.json", c);
  write_job(dir_ / "jobs" / "gallery.json", {{"jobs", {"b.json", "kov.json"}}});
  const std::string jobs = (dir_ / "jobs").string();
  ASSERT_EQ(epviz("check " + jobs + " --frames 0,100 --update").exit_code, 0);
  write_job(dir_ / "jobs" / "c.json", [&] {
    auto x = c;
    x["camera"] = {{"azimuth", 50.0}};
    return x;
  }());
  const auto one = epviz("check " + jobs + " --frames 0,100 -j 1");
  const auto two = epviz("check " + jobs + " --frames 0,100 -j 3");
  EXPECT_EQ(one.exit_code, 1);
  EXPECT_EQ(two.exit_code, 1);
  EXPECT_EQ(one.out, two.out);
  EXPECT_NE(one.out.find("4 passed, 2 failed"), std::string::npos) << one.out;
  // Job order: the directory's files by name, gallery jobs at the gallery's place, no job twice.
  const auto pb = one.out.find("b.json frame 0"), pc = one.out.find("c.json frame 0"),
             pk = one.out.find("kov.json frame 0");
  EXPECT_LT(pb, pc);
  EXPECT_LT(pc, pk);
}

TEST_F(Check, NumericalFailureFailsTheFramesFromThereOnAndWritesNoGoldens) {
  // A steady rotation carries gamma exactly through the south pole; the north
  // Riccati chart alone cannot follow it.
  auto j = small_job();
  j["simulation"] = {{"case", "euler"},          {"omega", {1, 0, 0}},    {"gamma", {0, 0.6, 0.8}},
                     {"formulation", "riccati"}, {"chart_switch", false}, {"t_end", 6.0}};
  j.erase("trail");
  write_job(job_, j);
  const auto u = epviz("check " + job() + " --update");
  EXPECT_EQ(u.exit_code, 1) << u.out << u.err;
  EXPECT_NE(u.out.find("numerical failure, no goldens written: dop853 failed at t = "),
            std::string::npos)
      << u.out;
  EXPECT_FALSE(fs::exists(golden(0).parent_path()));
  const auto r = epviz("check " + job());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("numerical failure before this frame"), std::string::npos) << r.out;
}

using BadCheck = epviz::test::RefusedCase;

// Goldens come from version control: a link, a FIFO or a golden.json that is
// not a file is refused before anything is drawn, and nothing is written
// through a link.
TEST_F(Check, HostileGoldensAreRefusedBeforeWork) {
  ASSERT_EQ(epviz("check " + job() + " --frames 0 --update").exit_code, 0);
  const auto victim = dir_ / "victim.txt";
  std::ofstream(victim) << "keep me";
  fs::remove(golden(0));
  fs::create_symlink(victim, golden(0));
  for (const char* mode : {"", " --update"})
    test::expect_bad_input(epviz("check " + job() + " --frames 0" + mode),
                           "frame_0000.png: a golden is a symbolic link");
  EXPECT_EQ(test::slurp(victim), "keep me");
  fs::remove(golden(0));
  ASSERT_EQ(mkfifo(golden(0).c_str(), 0600), 0);
  test::expect_bad_input(epviz("check " + job() + " --frames 0"), "a golden is not a regular file");
  fs::remove(golden(0));
  const auto record = golden(0).parent_path() / "golden.json";
  fs::remove(record);
  fs::create_directory(record);
  for (const char* mode : {"", " --update"})
    test::expect_bad_input(epviz("check " + job() + " --frames 0" + mode),
                           "golden.json: not a regular file");
  fs::remove(record);
  std::ofstream(record) << R"({"epviz_version": "1", "gl_renderer": "r", "gl_version": "v",)"
                        << R"( "frames": [-5]})";
  test::expect_bad_input(epviz("check " + job() + " --frames 0 --update"),
                         "golden.json: frames: -5 is not a frame");
}

class CheckRejects : public Check, public ::testing::WithParamInterface<BadCheck> {};

TEST_P(CheckRejects, WithOneLineExitTwoAndNothingWritten) {
  const auto& bad = GetParam();
  write_job(dir_ / "bench.json", {{"bench", {{"quick", true}}}});
  fs::create_directories(dir_ / "empty");
  if (!fs::exists(dir_ / "fifo.xml")) {
    ASSERT_EQ(mkfifo((dir_ / "fifo.xml").c_str(), 0600), 0);
  }
  std::string args = std::regex_replace(bad.args, std::regex("JOB"), job());
  args = std::regex_replace(args, std::regex("DIR"), dir_.path().string());
  const auto r = epviz("check " + args);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find(std::regex_replace(bad.must_name, std::regex("DIR"), dir_.path().string())),
            std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(dir_ / "jobs" / "golden"));
  EXPECT_FALSE(fs::exists(dir_ / "rep"));
  EXPECT_FALSE(fs::exists(dir_ / "j.xml"));
}

INSTANTIATE_TEST_SUITE_P(
    Input, CheckRejects,
    ::testing::Values(
        BadCheck{"unknown_metric", "JOB --metric mse --update",
                 "--metric: unknown metric 'mse' (allowed: pixel, ssim)"},
        BadCheck{"threshold_out_of_range", "JOB --threshold 256 --report DIR/rep", "--threshold"},
        BadCheck{"ssim_threshold_above_one", "JOB --metric ssim --threshold 2 --junit DIR/j.xml",
                 "--threshold: with --metric ssim"},
        BadCheck{"max_differing_with_ssim", "JOB --metric ssim --max-differing 1",
                 "--max-differing: applies to --metric pixel"},
        BadCheck{"max_differing_percent", "JOB --max-differing 150",
                 "--max-differing: expected a percentage"},
        BadCheck{"frames_past_the_end", "JOB --frames 0,260:300 --update", "kov.json: --frames"},
        BadCheck{"frames_empty_item", "JOB --frames 0,,3", "--frames: empty item"},
        BadCheck{"frames_syntax", "JOB --frames x --junit DIR/j.xml", "--frames"},
        BadCheck{"workers", "JOB -j 0", "-j"},
        BadCheck{"unknown_gl", "JOB --gl vulkan --update", "--gl: unknown GL backend 'vulkan'"},
        BadCheck{"report_parent_missing", "JOB --report DIR/no/such/rep", "--report: directory"},
        BadCheck{"report_takes_no_files", "JOB --report /proc/self",
                 "--report: cannot create files in '/proc/self'"},
        BadCheck{"report_under_proc", "JOB --report /proc/epviz-report",
                 "--report: cannot create files in '/proc/epviz-report'"},
        BadCheck{"golden_folder_under_a_file", "JOB --golden DIR/jobs/kov.json",
                 "kov.json: the golden folder"},
        BadCheck{"junit_fifo_nobody_reads", "JOB --junit DIR/fifo.xml",
                 "--junit: 'DIR/fifo.xml' is a FIFO that nobody reads"},
        BadCheck{"junit_parent_missing", "JOB --junit DIR/no/j.xml", "--junit: directory"},
        BadCheck{"missing_job", "DIR/none.json --update", "none.json: cannot open"},
        BadCheck{"bench_job", "DIR/bench.json",
                 "bench.json: a bench-figures job has no frames to check"},
        BadCheck{"empty_directory", "DIR/empty", "empty: no render jobs"}),
    epviz::test::case_name);

}  // namespace
}  // namespace epviz
