#include <gtest/gtest.h>

#include <string>

#include "io/frame_range.hpp"

namespace {

using namespace epviz::io;

std::string error_of(std::string_view text, int frame_count) {
  try {
    parse_frame_range(text, frame_count);
  } catch (const FrameRangeError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(FrameRange, EveryFormInclusive) {
  EXPECT_EQ(parse_frame_range("10:20", 100), (FrameRange{10, 20}));
  EXPECT_EQ(parse_frame_range("10:20", 100).count(), 11);
  EXPECT_EQ(parse_frame_range("10:", 100), (FrameRange{10, 99}));
  EXPECT_EQ(parse_frame_range(":20", 100), (FrameRange{0, 20}));
  EXPECT_EQ(parse_frame_range("42", 100), (FrameRange{42, 42}));
  EXPECT_EQ(parse_frame_range("42", 100).count(), 1);
  EXPECT_EQ(parse_frame_range("0:99", 100), all_frames(100));
  EXPECT_EQ(parse_frame_range("5:5", 100), (FrameRange{5, 5}));
  EXPECT_EQ(parse_frame_range("0", 1), (FrameRange{0, 0}));
  EXPECT_EQ(parse_frame_range("007:010", 100), (FrameRange{7, 10}));
  EXPECT_TRUE(parse_frame_range("3:5", 10).contains(5));
  EXPECT_FALSE(parse_frame_range("3:5", 10).contains(6));
}

TEST(FrameRange, SyntaxOnlyKeepsOpenEnds) {
  const FrameRangeSpec open_end = parse_frame_range("3:");
  EXPECT_EQ(open_end.first, 3);
  EXPECT_FALSE(open_end.last.has_value());
  const FrameRangeSpec open_start = parse_frame_range(":8");
  EXPECT_FALSE(open_start.first.has_value());
  EXPECT_EQ(open_start.last, 8);
}

TEST(FrameRange, MalformedValuesNameTheOptionAndTheForms) {
  for (const char* text : {"", ":", "a:b", "1:2:3", "-1", "1:-2", "1.5", " 1:2", "1 :2", "+3",
                           "1:x", "x", "99999999999999999999"}) {
    const std::string message = error_of(text, 100);
    EXPECT_NE(message.find("--frames"), std::string::npos) << text << ": " << message;
    EXPECT_NE(message.find("allowed: A:B"), std::string::npos) << text << ": " << message;
    EXPECT_NE(message.find("A:"), std::string::npos) << message;
    EXPECT_NE(message.find(":B"), std::string::npos) << message;
    EXPECT_THROW(parse_frame_range(std::string_view(text)), FrameRangeError) << text;
  }
  EXPECT_NE(error_of("1:2:3", 100).find("more than one ':'"), std::string::npos);
  EXPECT_NE(error_of("", 100).find("empty value"), std::string::npos);
  EXPECT_NE(error_of("a:2", 100).find("first frame 'a'"), std::string::npos);
  EXPECT_NE(error_of("99999999999999999999", 100).find("too large"), std::string::npos);
}

TEST(FrameRange, AListIsRangesSeparatedByCommas) {
  EXPECT_TRUE(parse_frame_ranges("").empty());
  const auto specs = parse_frame_ranges("4,10:12,:3,7:");
  ASSERT_EQ(specs.size(), 4u);
  EXPECT_EQ(specs[0].first, 4);
  EXPECT_EQ(specs[0].last, 4);
  EXPECT_EQ(specs[1].first, 10);
  EXPECT_EQ(specs[1].last, 12);
  EXPECT_FALSE(specs[2].first.has_value());
  EXPECT_FALSE(specs[3].last.has_value());
}

TEST(FrameRange, AListRefusesAnEmptyItemAndABadOne) {
  for (const char* text : {",", "1,", ",1", "1,,2"}) {
    try {
      parse_frame_ranges(text);
      ADD_FAILURE() << text << " was accepted";
    } catch (const FrameRangeError& e) {
      EXPECT_NE(std::string(e.what()).find("empty item in '" + std::string(text) + "'"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_THROW(parse_frame_ranges("1,a:2"), FrameRangeError);
}

TEST(FrameRange, EmptyRangeIsAnError) {
  const std::string message = error_of("20:10", 100);
  EXPECT_NE(message.find("--frames '20:10'"), std::string::npos) << message;
  EXPECT_NE(message.find("empty"), std::string::npos) << message;
}

TEST(FrameRange, OutOfRangeIsAnErrorNotClamped) {
  for (const char* text : {"100", "0:100", "100:", "150:200", ":100"}) {
    const std::string message = error_of(text, 100);
    EXPECT_NE(message.find("--frames"), std::string::npos) << message;
    EXPECT_NE(message.find("out of range"), std::string::npos) << text << ": " << message;
    EXPECT_NE(message.find("100 frames, numbered 0 to 99"), std::string::npos) << message;
  }
  EXPECT_NE(error_of("0", 0).find("no frames"), std::string::npos);
  EXPECT_THROW(resolve_frame_range(FrameRangeSpec{5, 3}, 10), FrameRangeError);
}

}  // namespace
