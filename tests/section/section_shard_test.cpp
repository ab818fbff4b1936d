// A section split into shards and joined by `epviz merge` is the section run
// in one process: the same CSV byte for byte and the same pictures; a missing
// shard is named with the command that runs it, as for sweeps.
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "shard/manifest.hpp"
#include "support/cli.hpp"

namespace epviz::test {
namespace {

namespace fs = std::filesystem;

// Seven orbits of one level in three shards (3, 2, 2 orbits), with a picture
// of each kind; the outputs are named relative to where epviz runs.
const char* const kSection = R"({"case": "kovalevskaya", "level": {"energy": 2, "area": 0.5},
    "orbits": 7, "crossings": 30, "csv": "k.csv", "png": "k.png", "svg": "k.svg"})";

struct Folders {
  TempDir d;
  fs::path file = d / "k.section.json", whole = d / "whole", shards = d / "shards";
  Folders(const std::string& text = kSection) {
    std::ofstream(file) << text;
    fs::create_directories(whole);
    fs::create_directories(shards);
  }
  // `epviz ARGS` run in `folder` (with `env`, "NAME=value ...", in its environment).
  CliResult run(const fs::path& folder, const std::string& args, const std::string& env = "") {
    return run_epviz(args, d, "cd " + folder.string() + " && env " + env);
  }
};

TEST(SectionShard, ThreeShardsMergedAreTheUnshardedSection) {
  Folders f;
  const auto whole = f.run(f.whole, "section " + f.file.string() + " -j 2");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  for (int i = 0; i < 3; ++i) {
    const auto r =
        f.run(f.shards, "section " + f.file.string() + " -j 1 --shard " + std::to_string(i) + "/3");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(fs::exists(f.shards / "k.csv")) << "a shard writes only its own rows";
  }
  const auto merged = f.run(f.d.path(), "merge " + f.shards.string());
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  const std::string csv = slurp(f.whole / "k.csv");
  EXPECT_EQ(line_count(csv), 1u + 7u * 30u);
  EXPECT_EQ(slurp(f.shards / "k.csv"), csv);
  EXPECT_EQ(slurp(f.shards / "k.svg"), slurp(f.whole / "k.svg"));
  EXPECT_EQ(slurp(f.shards / "k.png"), slurp(f.whole / "k.png"));
}

// The shard comes from a Slurm array's environment as for a sweep; the
// merge of an incomplete batch names the missing shard with its command and
// exits with 4, writing nothing.
TEST(SectionShard, AMissingShardIsNamedWithTheCommandThatRunsIt) {
  Folders f;
  for (int task : {1, 3}) {  // --array=1-3: tasks 1 and 3 are shards 0 and 2
    const auto r = f.run(f.shards, "section " + f.file.string() + " -j 1",
                         "SLURM_ARRAY_TASK_ID=" + std::to_string(task) +
                             " SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=3");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  EXPECT_TRUE(fs::exists(f.shards / "k.shard-0-of-3.csv"));
  EXPECT_TRUE(fs::exists(f.shards / "k.shard-2-of-3.csv"));
  const auto merged = f.run(f.d.path(), "merge " + f.shards.string());
  EXPECT_EQ(merged.exit_code, 4) << merged.err;
  const std::string redo = "shard 1/3: missing (no manifest in " + f.shards.string() +
                           "); run: epviz section " + f.file.string() + " --out " +
                           (f.shards / "k.csv").string() + " -j 1 --shard 1/3";
  EXPECT_NE(merged.err.find(redo), std::string::npos) << merged.err;
  EXPECT_FALSE(fs::exists(f.shards / "k.csv"));
  // Running the command named completes the batch.
  const auto again = f.run(f.d.path(), redo.substr(redo.find("section ")));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(f.run(f.d.path(), "merge " + f.shards.string()).exit_code, 0);
  EXPECT_EQ(line_count(slurp(f.shards / "k.csv")), 1u + 7u * 30u);
}

// A section file edited after its shards ran is not the one they ran: the
// merge refuses (exit 2) rather than naming the runs or drawing by the new one.
TEST(SectionShard, TheMergeRefusesASectionFileChangedSince) {
  Folders f;
  for (int i = 0; i < 2; ++i)
    ASSERT_EQ(f.run(f.shards, "section " + f.file.string() + " --shard " + std::to_string(i) + "/2")
                  .exit_code,
              0);
  std::string text = kSection;
  text.replace(text.find("\"crossings\": 30"), 15, "\"crossings\": 31");
  std::ofstream(f.file) << text;
  expect_bad_input(f.run(f.d.path(), "merge " + f.shards.string()), "changed since");
}

// The merge writes a section's pictures into its output folder under their
// file names: a name that is one of the merge's own files there (the merged
// CSV, a shard's CSV or manifest, the section file) is refused before
// anything is written, and that file is left as it was.
TEST(SectionShard, PicturesNamingTheMergesOwnFilesAreRefused) {
  struct Case {
    std::string key, name, out, must_name;
  };
  for (const auto& c :
       {Case{"png", "k.csv", "", "the merged output"},
        Case{"png", "k.shard-0-of-2.csv", "", "a file of shard 0/2"},
        Case{"svg", "k.shard-1-of-2.manifest.json", "", "the manifest of shard 1/2"},
        Case{"svg", "k.section.json", "..", "the section file"}}) {
    SCOPED_TRACE(c.name);
    std::string text = kSection;
    text.replace(text.find("\"" + c.key + "\": \"k."), 13, "\"" + c.key + "\": \"sub/" + c.name);
    Folders f(text);
    fs::create_directories(f.shards / "sub");
    for (int i = 0; i < 2; ++i)
      ASSERT_EQ(
          f.run(f.shards, "section " + f.file.string() + " --shard " + std::to_string(i) + "/2")
              .exit_code,
          0);
    const fs::path out = c.out.empty() ? f.shards : f.d.path();
    std::map<fs::path, std::string> before;
    for (const auto& e : fs::directory_iterator(out))
      if (e.is_regular_file()) before[e.path()] = slurp(e.path());
    const auto r = f.run(f.d.path(), "merge " + f.shards.string() + " --out " + out.string());
    expect_bad_input(r, "the " + std::string(c.key == "png" ? "PNG" : "SVG") + " of section");
    EXPECT_NE(r.err.find(c.must_name), std::string::npos) << r.err;
    std::map<fs::path, std::string> after;
    for (const auto& e : fs::directory_iterator(out))
      if (e.is_regular_file()) after[e.path()] = slurp(e.path());
    EXPECT_TRUE(before == after) << "the merge wrote in " << out;
  }
}

// A shard's CSV is a file anyone may edit: a value that is not a finite
// number ("nan", "inf") is refused naming the file, line and column, though
// the manifest was made to match it.
TEST(SectionShard, AValueThatIsNotAFiniteNumberIsRefused) {
  for (const std::string bad : {"nan", "-inf", "1e999"}) {
    SCOPED_TRACE(bad);
    Folders f;
    for (int i = 0; i < 2; ++i)
      ASSERT_EQ(
          f.run(f.shards, "section " + f.file.string() + " --shard " + std::to_string(i) + "/2")
              .exit_code,
          0);
    const fs::path manifest = f.shards / "k.shard-0-of-2.manifest.json";
    shard::Manifest m = shard::read_manifest(manifest);
    const fs::path csv = f.shards / m.files.at(0).path;
    std::string text = slurp(csv);
    // Line 3, column omega1 (the fourth): orbit,crossing,t,omega1,...
    std::size_t at = text.find('\n', text.find('\n') + 1) + 1;
    for (int comma = 0; comma < 3; ++comma) at = text.find(',', at) + 1;
    text.replace(at, text.find(',', at) - at, bad);
    std::ofstream(csv, std::ios::trunc) << text;
    m.files.clear();
    shard::add_file(m, f.shards, csv);
    shard::write_manifest(manifest, m);
    const auto r = f.run(f.d.path(), "merge " + f.shards.string());
    expect_bad_input(r, "k.shard-0-of-2.csv: line 3: column 'omega1'");
    EXPECT_FALSE(fs::exists(f.shards / "k.csv")) << "merged despite exit 2";
  }
}

// A shard that cannot be one is refused before any orbit runs.
TEST(SectionShard, BadShardOptionsAreRefused) {
  Folders f;
  const std::string section = "section " + f.file.string();
  expect_bad_input(f.run(f.shards, section + " --shard 3/3"), "--shard");
  expect_bad_input(f.run(f.shards, section + " --out - --shard 0/2"), "--shard");
  expect_bad_input(f.run(f.shards, section, "JOB_COMPLETION_INDEX=1"), "--shard-count");
  EXPECT_TRUE(fs::is_empty(f.shards));
}

}  // namespace
}  // namespace epviz::test
