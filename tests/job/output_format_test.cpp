// A render job's output format: "png" (PNG frames) or one of io's video
// formats, read from a job and written back under the same name.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/bad_input.hpp"
#include "job/schema.hpp"

namespace epviz::job {
namespace {

JobDocument with_format(const std::string& format) {
  return read_job(
      nlohmann::json{{"simulation", {{"case", "euler"}}}, {"output", {{"format", format}}}},
      "job.json");
}

TEST(OutputFormat, PngAndEveryVideoFormatAreNamed) {
  const std::vector<std::string> expected{"png", "mp4", "webm", "gif"};
  EXPECT_EQ(output_format_names(), expected);
}

TEST(OutputFormat, PngMeansNoVideoAndAVideoNameItsFormat) {
  EXPECT_EQ(with_format("png").output.video, std::nullopt);
  EXPECT_EQ(with_format("webm").output.video, io::VideoFormat::webm);
  EXPECT_EQ(with_format("gif").output.video, io::VideoFormat::gif);
  EXPECT_EQ(read_job(nlohmann::json{{"simulation", {{"case", "euler"}}}}, "job.json").output.video,
            std::nullopt);
}

TEST(OutputFormat, EachFormatIsWrittenBackUnderItsName) {
  for (const auto& name : output_format_names())
    EXPECT_EQ(write_job(with_format(name))["output"]["format"], name);
}

TEST(OutputFormat, AnUnknownFormatIsRefusedListingTheAllowedOnes) {
  try {
    with_format("avi");
    ADD_FAILURE() << "avi was accepted";
  } catch (const io::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("png, mp4, webm, gif"), std::string::npos) << e.what();
  }
}

TEST(OutputFormat, AFormatOptionIsCheckedAndNamedInItsError) {
  EXPECT_EQ(parse_output_format("--format", "png"), std::nullopt);
  EXPECT_EQ(parse_output_format("--format", "gif"), io::VideoFormat::gif);
  try {
    parse_output_format("--format", "avi");
    ADD_FAILURE() << "avi was accepted";
  } catch (const io::BadInput& e) {
    EXPECT_EQ(std::string(e.what()),
              "--format: unknown format 'avi' (allowed: png, mp4, webm, gif)");
  }
}

}  // namespace
}  // namespace epviz::job
