// JUnit XML and the HTML report of check results, golden.json, and the job
// file fingerprint (FNV-1a 64 against the published test vectors).
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "check/golden_record.hpp"
#include "check/html_report.hpp"
#include "check/junit_xml.hpp"
#include "io/fnv1a.hpp"

namespace epviz::check {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

std::vector<FrameResult> sample_results() {
  FrameResult a{"jobs/a.json", 0, true, "0 % pixels differ (limit 1 %)", "", "", "", ""};
  FrameResult b{"jobs/a.json", 44,      false,  "3.50 % pixels differ (limit 1 %)", "",
                "g.png",       "a.png", "d.png"};
  FrameResult c{"jobs/<b>&\"c\".json",
                0,
                false,
                "",
                "no golden x; create it with: epviz check 'b' --update",
                "",
                "",
                ""};
  return {a, b, c};
}

TEST(Junit, OneTestcasePerFrameAndOneSuitePerJob) {
  const auto x = junit_xml(sample_results(), 1.5);
  EXPECT_EQ(count(x, "<testsuite "), 2u);
  EXPECT_EQ(count(x, "<testcase "), 3u);
  EXPECT_EQ(count(x, "<failure "), 2u);
  EXPECT_NE(x.find("<testsuites name=\"epviz check\" tests=\"3\" failures=\"2\""),
            std::string::npos)
      << x;
  EXPECT_NE(x.find("<testsuite name=\"jobs/a.json\" tests=\"2\" failures=\"1\""), std::string::npos)
      << x;
  EXPECT_NE(x.find("jobs/&lt;b&gt;&amp;&quot;c&quot;.json"), std::string::npos) << x;
  EXPECT_EQ(x.find("<b>"), std::string::npos);
}

TEST(Junit, EscapesEverythingXmlReserves) {
  EXPECT_EQ(xml_escape("a<b>&\"c'\x01"), "a&lt;b&gt;&amp;&quot;c&apos;?");
}

TEST(Summary, CountsPassedAndFailed) { EXPECT_EQ(summary(sample_results()), "1 passed, 2 failed"); }

TEST(Lines, SayPassOrFailJobFrameAndTheMeasure) {
  const auto r = sample_results();
  EXPECT_EQ(r[0].line(), "PASS jobs/a.json frame 0: 0 % pixels differ (limit 1 %)");
  EXPECT_EQ(r[1].line(), "FAIL jobs/a.json frame 44: 3.50 % pixels differ (limit 1 %)");
}

TEST(HtmlReport, ShowsTheThreeImagesOfFailingFramesOnly) {
  const auto h = html_report(sample_results(), {"tolerance text", "llvmpipe"});
  EXPECT_NE(h.find("<img src=\"g.png\""), std::string::npos);
  EXPECT_NE(h.find("<img src=\"a.png\""), std::string::npos);
  EXPECT_NE(h.find("<img src=\"d.png\""), std::string::npos);
  EXPECT_EQ(count(h, "<section "), 2u);
  EXPECT_NE(h.find("jobs/a.json frame 44"), std::string::npos);
  EXPECT_NE(h.find("tolerance text"), std::string::npos);
  EXPECT_EQ(h.find("<b>&"), std::string::npos);  // names are escaped
}

TEST(Fnv1a64, PublishedTestVectors) {
  EXPECT_EQ(io::fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(io::fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(io::fnv1a64("foobar"), 0x85944171f73967e8ull);
}

TEST(GoldenRecord, RoundTripsThroughGoldenJson) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("epviz-golden-" + std::to_string(::getpid()) + ".json");
  GoldenRecord r{"0.1.0",
                 "llvmpipe (LLVM 15)",
                 "4.5 (Core Profile) Mesa 22.3.6",
                 "a.json",
                 "fnv1a64:00",
                 {0, 5, 9},
                 160,
                 120};
  std::ofstream(file) << to_json_text(r);
  const auto back = read_golden_record(file);
  std::filesystem::remove(file);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->gl_renderer, r.gl_renderer);
  EXPECT_EQ(back->gl_version, r.gl_version);
  EXPECT_EQ(back->frames, r.frames);
  EXPECT_EQ(back->width, 160);
  EXPECT_FALSE(read_golden_record(file));
}

}  // namespace
}  // namespace epviz::check
