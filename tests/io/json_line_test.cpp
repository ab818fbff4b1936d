// The compact JSON writer against nlohmann's reader: what it writes parses,
// and reads back as the values written (doubles bit for bit).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include <nlohmann/json.hpp>

#include "io/json_line.hpp"

namespace epviz::io {
namespace {

using nlohmann::json;

TEST(JsonLine, NestedContainersReadBackAsWritten) {
  JsonLine j;
  j.begin_object();
  j.key("a").value(1L).key("b").begin_array().value(true).null().value("x").end_array();
  j.key("c").begin_object().key("d").triple(1.5, -2.0, 0.25).end_object();
  j.key("e").begin_array().end_array().key("f").begin_object().end_object();
  j.key("g").raw(R"({"h":[1,2]})");
  j.end_object();
  const json back = json::parse(j.str());
  const json expected = json::parse(
      R"({"a":1,"b":[true,null,"x"],"c":{"d":[1.5,-2.0,0.25]},"e":[],"f":{},"g":{"h":[1,2]}})");
  EXPECT_EQ(back, expected) << j.str();
  EXPECT_EQ(j.str().find(' '), std::string::npos) << "compact: no spaces";
}

TEST(JsonLine, DoublesRoundTripExactlyAndStayFloatingPoint) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::uint64_t> bits;
  JsonLine j;
  j.begin_array();
  std::vector<double> written = {0.0, 10.0, -3.0, 1e-10, 0.1, 1e300, 5e-324, 2.0 / 3.0};
  while (written.size() < 2000) {
    const std::uint64_t b = bits(rng);
    double x;
    std::memcpy(&x, &b, sizeof x);
    if (std::isfinite(x)) written.push_back(x);
  }
  for (double x : written) j.value(x);
  j.end_array();
  const json back = json::parse(j.str());
  ASSERT_EQ(back.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    EXPECT_TRUE(back[i].is_number_float()) << i << ": " << back[i].dump();
    EXPECT_EQ(back[i].get<double>(), written[i]) << i;
  }
}

TEST(JsonLine, NonFiniteDoublesAreNull) {
  JsonLine j;
  j.begin_array()
      .value(std::numeric_limits<double>::quiet_NaN())
      .value(std::numeric_limits<double>::infinity())
      .value(-std::numeric_limits<double>::infinity())
      .end_array();
  EXPECT_EQ(j.str(), "[null,null,null]");
}

TEST(JsonLine, StringsAndKeysAreEscaped) {
  const std::string nasty = "quote \" backslash \\ newline \n tab \t bell \a nul";
  std::string with_nul = nasty;
  with_nul += '\0';
  with_nul += "end, and UTF-8 \xc3\xa9";
  JsonLine j;
  j.begin_object().key(with_nul).value(with_nul).end_object();
  EXPECT_EQ(j.str().find('\n'), std::string::npos) << "one line";
  const json back = json::parse(j.str());
  ASSERT_TRUE(back.contains(with_nul));
  EXPECT_EQ(back[with_nul].get<std::string>(), with_nul);
}

TEST(JsonLine, IntegersKeepTheirValue) {
  JsonLine j;
  j.begin_array()
      .value(std::numeric_limits<long>::max())
      .value(std::numeric_limits<long>::min())
      .value(0)
      .end_array();
  const json back = json::parse(j.str());
  EXPECT_EQ(back[0].get<long>(), std::numeric_limits<long>::max());
  EXPECT_EQ(back[1].get<long>(), std::numeric_limits<long>::min());
  EXPECT_TRUE(back[2].is_number_integer());
}

}  // namespace
}  // namespace epviz::io
