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
  FrameResult a{"jobs/a.json", 0, true, "0 % pixels differ (limit 1 %)", "", "", "", "", 0.25};
  FrameResult b{"jobs/a.json", 44,      false, "3.50 % pixels differ (limit 1 %)", "", "g.png",
                "a.png",       "d.png", 1.5};
  FrameResult c{"jobs/<b>&\"c\".json",
                0,
                false,
                "",
                "no golden x; create it with: epviz check 'b' --update",
                "",
                "",
                "",
                0.125};
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

// Jenkins and GitLab show a testcase's time and the files its system-out
// names as [[ATTACHMENT|path]], relative to the directory the check ran in.
TEST(Junit, EachFrameHasItsTimeAndItsReportImagesAsAttachments) {
  const auto x = junit_xml(sample_results(), 2.0, "render-report");
  EXPECT_NE(x.find("<testcase classname=\"jobs/a.json\" name=\"frame 0\" time=\"0.250\">"),
            std::string::npos)
      << x;
  EXPECT_NE(x.find("name=\"frame 44\" time=\"1.500\">"), std::string::npos) << x;
  EXPECT_NE(x.find("<testsuite name=\"jobs/a.json\" tests=\"2\" failures=\"1\" errors=\"0\" "
                   "skipped=\"0\" time=\"1.750\">"),
            std::string::npos)
      << x;
  const auto frame44 = x.substr(x.find("name=\"frame 44\""));
  const auto out = frame44.substr(0, frame44.find("</testcase>"));
  for (const char* image : {"g.png", "a.png", "d.png"})
    EXPECT_NE(out.find(std::string("\n[[ATTACHMENT|render-report/") + image + "]]"),
              std::string::npos)
        << out;
  EXPECT_NE(out.find("</failure>\n      <system-out>"), std::string::npos) << out;
  EXPECT_EQ(count(x, "[[ATTACHMENT|"), 3u);  // frames without images have none
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
                 "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                 "fnv1a64:0123456789abcdef",
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
  EXPECT_EQ(back->font_file, r.font_file);
  EXPECT_EQ(back->font_hash, r.font_hash);
  EXPECT_EQ(back->frames, r.frames);
  EXPECT_EQ(back->width, 160);
  EXPECT_FALSE(read_golden_record(file));
}

}  // namespace
}  // namespace epviz::check
