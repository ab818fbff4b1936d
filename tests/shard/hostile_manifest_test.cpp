// A manifest is read as hostile input: whatever would make a merge write or
// read outside its folder, run ffmpeg on other files, leave items to no shard
// or echo a foreign command as advice is refused on one line naming the file
// and key, and the manifests epviz writes still read.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/bad_input.hpp"
#include "shard/manifest.hpp"
#include "support/temp_dir.hpp"

namespace epviz::shard {
namespace {

using Json = nlohmann::json;

// A lawful manifest as epviz writes it: shard 1 of 2 of a 4-point sweep.
Json lawful() {
  return Json::parse(R"({"kind":"sweep","source":"/s/a.sweep.json","hash":"00ff",
    "shard":1,"shards":2,"first":2,"end":4,"total":4,
    "command":["epviz","sweep","/s/a.sweep.json","--out","/r/a.jsonl","-j","2"],
    "output":"a.jsonl","files":[{"path":"a.shard-1-of-2.jsonl","bytes":3,"checksum":"0123456789abcdef"}],
    "completed":true})");
}

// The same of a render to video.
Json lawful_render() {
  auto j = lawful();
  j["kind"] = "render";
  j["output"] = "movie.mp4";
  j["command"] = {"epviz",    "render", "/s/a.sweep.json", "--out", "/r", "--width", "64",
                  "--height", "48",     "--format",        "mp4"};
  j["files"][0]["path"] = "movie.shard-1-of-2.mp4";
  return j;
}

struct HostileCase {
  std::string name;
  std::string pointer;  // the value replaced, as a JSON pointer
  Json value;
  std::string must_name;  // in the message
  bool render = false;    // of lawful_render(), else of lawful()
};
void PrintTo(const HostileCase& c, std::ostream* os) { *os << c.name; }

class HostileManifest : public ::testing::TestWithParam<HostileCase> {};

TEST(HostileManifest, TheLawfulManifestReads) {
  test::TempDir d;
  std::ofstream(d / "m.json") << lawful().dump();
  const auto m = read_manifest(d / "m.json");
  EXPECT_EQ(m.output, "a.jsonl");
  EXPECT_EQ(rerun_command(m, 0), "epviz sweep /s/a.sweep.json --out /r/a.jsonl -j 2 --shard 0/2");
  std::ofstream(d / "m.json", std::ios::trunc) << lawful_render().dump();
  EXPECT_EQ(read_manifest(d / "m.json").kind, "render");
}

TEST_P(HostileManifest, IsRefusedOnOneLineNamingTheKey) {
  const auto& c = GetParam();
  test::TempDir d;
  auto j = c.render ? lawful_render() : lawful();
  j[Json::json_pointer(c.pointer)] = c.value;
  std::ofstream(d / "m.json") << j.dump();
  try {
    read_manifest(d / "m.json");
    FAIL() << "accepted " << c.pointer << " = " << c.value.dump();
  } catch (const io::BadInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("m.json: key '" + c.must_name + "'"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_LT(what.size(), 500u) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, HostileManifest,
    ::testing::Values(
        HostileCase{"AbsoluteOutput", "/output", "/abs/victim", "output"},
        HostileCase{"OutputUpwards", "/output", "../victim", "output"},
        HostileCase{"OutputInASubfolder", "/output", "sub/victim", "output"},
        HostileCase{"OutputDotDot", "/output", "..", "output"},
        HostileCase{"EmptyOutputOfASweep", "/output", "", "output"},
        HostileCase{"FileUpwards", "/files/0/path", "../x", "files[0].path"},
        HostileCase{"FileUpwardsInside", "/files/0/path", "a/../../x", "files[0].path"},
        HostileCase{"AbsoluteFile", "/files/0/path", "/etc/passwd", "files[0].path"},
        HostileCase{"UnknownKind", "/kind", "rows", "kind"},
        HostileCase{"KindOtherThanTheCommands", "/kind", "render", "command"},
        HostileCase{"RenderOfARowsFile", "/files/0/path", "a.shard-1-of-2.jsonl", "files[0].path",
                    true},
        HostileCase{"RenderToARowsFile", "/output", "a.jsonl", "files[0].path", true},
        HostileCase{"RenderOptionOfASweep", "/command/3", "-j", "command", true},
        HostileCase{"ForeignCommand", "/command", Json{"rm", "-rf", "/"}, "command"},
        HostileCase{"ForeignOption", "/command/5", "--exec", "command"},
        HostileCase{"CommandOfAnotherSource", "/command/2", "/s/b.sweep.json", "command"},
        HostileCase{"CommandOnTwoLines", "/command/4", "/r/a.jsonl\nrm -rf /", "command"},
        HostileCase{"SourceOnTwoLines", "/source", "/s/a\n.sweep.json", "source"},
        HostileCase{"HashNotHex", "/hash", "../../x", "hash"},
        HostileCase{"ChecksumNotHex", "/files/0/checksum", "$(rm)", "files[0].checksum"},
        HostileCase{"RangeWithAGap", "/first", 3, "first"},
        HostileCase{"RangeOfAnotherShard", "/end", 3, "first"}),
    [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace epviz::shard
