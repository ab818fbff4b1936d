// Strict JSON reading under hostile files: errors, never crashes; every
// message on one line and short, whatever the value or key holds.
#include <gtest/gtest.h>
#include <sys/ioctl.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "io/json_reader.hpp"
#include "io/printable.hpp"
#include "support/errors.hpp"
#include "support/eventually.hpp"
#include "support/temp_dir.hpp"

namespace {

using epviz::io::BadInput;
using epviz::io::describe;
using epviz::io::ObjectReader;
using epviz::io::parse_json_text;
using epviz::io::printable;
using nlohmann::json;

// The message of the BadInput `f` throws; fails the test if it throws none.
template <class F>
std::string error_of(F&& f) {
  return epviz::test::error_of<BadInput>(f);
}

std::string nested_arrays(int depth, const std::string& inner = "1") {
  return std::string(std::size_t(depth), '[') + inner + std::string(std::size_t(depth), ']');
}

bool one_line(const std::string& s) { return s.find('\n') == std::string::npos; }

TEST(JsonReader, NestingIsBoundedOnParse) {
  const std::string deep = R"({"title": )" + nested_arrays(100'000) + "}";
  const auto message = error_of([&] { parse_json_text(deep, "deep.json"); });
  EXPECT_NE(message.find("deep.json: key 'title"), std::string::npos) << message.substr(0, 300);
  EXPECT_NE(message.find("nested deeper than 64"), std::string::npos) << message.substr(0, 300);
  EXPECT_LT(message.size(), 400u);
}

TEST(JsonReader, NestingUpToTheLimitIsRead) {
  // The root object is one level, so 63 arrays inside it reach the limit.
  const auto at_limit = parse_json_text(R"({"a": )" + nested_arrays(63) + "}", "ok.json");
  EXPECT_TRUE(at_limit["a"].is_array());
  EXPECT_THROW(parse_json_text(R"({"a": )" + nested_arrays(64) + "}", "ok.json"), BadInput);
}

TEST(JsonReader, DuplicateKeysAreRefusedByPath) {
  const auto message =
      error_of([] { parse_json_text(R"({"camera": {"azimuth": 1, "azimuth": 2}})", "d.json"); });
  EXPECT_NE(message.find("d.json: key 'camera.azimuth': given twice"), std::string::npos)
      << message;
  // The same key in two different objects is fine.
  EXPECT_NO_THROW(
      parse_json_text(R"({"a": {"x": 1}, "b": {"x": 2}, "c": [{"x": 1}, {"x": 2}]})", "ok.json"));
}

TEST(JsonReader, NumberOverflowNamesTheKey) {
  auto message = error_of([] { parse_json_text(R"({"simulation": {"t_end": 1e400}})", "o.json"); });
  EXPECT_NE(message.find("o.json: key 'simulation.t_end': the number 1e400 is out of range"),
            std::string::npos)
      << message;
  message = error_of([] { parse_json_text(R"({"v": [1, -1e999, 3]})", "o.json"); });
  EXPECT_NE(message.find("key 'v[1]'"), std::string::npos) << message;
}

// The value read is the one the plain parser gives: every kind of value, in
// objects and arrays, nested, with the keys in their places.
TEST(JsonReader, TheValueReadIsThePlainParsersValue) {
  const std::string text = R"({"a": [1, -2, 3.5, 1e300, 18446744073709551615, true, false, null,
      "s\u00e9", {"b": [[], {}], "c": {"d": [{"e": 1}, {"e": 2}]}}], "f": {}, "g": []})";
  EXPECT_EQ(parse_json_text(text, "v.json"), json::parse(text));
}

// Many objects in one array are read in time linear in their number: the
// callback parser this replaced scanned the array at each object's end (a
// 1.2 MB job took 80 s to refuse). 200,000 objects took 20 s with it, and
// take a few hundredths of a second now; the bound leaves a loaded or
// sanitised build a hundredfold margin.
TEST(JsonReader, ManyObjectsInOneArrayAreReadInLinearTime) {
  std::string text = R"({"rows": [)";
  for (int i = 0; i < 200'000; ++i) text += (i ? ", " : "") + std::string(R"({"x": 1, "y": [2]})");
  text += "]}";
  const auto start = std::chrono::steady_clock::now();
  const auto value = parse_json_text(text, "wide.json");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(value["rows"].size(), 200'000u);
  EXPECT_EQ(value["rows"][199'999]["y"][0], 2);
  EXPECT_LT(seconds, 5.0);
  // A duplicate key deep in the last element is still named by its path.
  text.insert(text.size() - 3, R"(, "x": 3)");
  const auto message = error_of([&] { parse_json_text(text, "wide.json"); });
  EXPECT_NE(message.find("key 'rows[199999].x': given twice"), std::string::npos) << message;
}

TEST(JsonReader, SyntaxErrorsNameLineAndColumn) {
  const auto message = error_of([] { parse_json_text("{\n  \"a\": x\n}", "s.json"); });
  EXPECT_EQ(message.rfind("s.json:2:", 0), 0u) << message;
}

TEST(JsonReader, TheRootMustBeAnObject) {
  EXPECT_NE(error_of([] { parse_json_text("[1, 2]", "r.json"); }).find("must be a JSON object"),
            std::string::npos);
}

TEST(JsonReader, DescribeIsShortAndOneLineForAnyValue) {
  // Built without the parser, so deeper than it would allow.
  json deep = 1;
  for (int i = 0; i < 100'000; ++i) {
    json outer = json::array();
    outer.push_back(std::move(deep));
    deep = std::move(outer);
  }
  const auto d = describe(deep);
  EXPECT_EQ(d.rfind("an array [[[[", 0), 0u) << d;
  EXPECT_LT(d.size(), 100u);

  const auto big = describe(json(std::string(10'000'000, 'x')));
  EXPECT_EQ(big.rfind("a string \"xxx", 0), 0u) << big;
  EXPECT_LT(big.size(), 100u);

  const auto lines = describe(json{{"a\nb", "c\rd"}});
  EXPECT_TRUE(one_line(lines)) << lines;
  EXPECT_NE(lines.find("a\\nb"), std::string::npos) << lines;
  EXPECT_NE(lines.find("c\\rd"), std::string::npos) << lines;

  EXPECT_EQ(describe(json(2.5)), "the number 2.5");
  EXPECT_EQ(describe(json(7)), "the integer 7");
  EXPECT_EQ(describe(json(true)), "true");
}

TEST(JsonReader, UnknownKeysAndChoicesAreQuotedOnOneLine) {
  const auto j = parse_json_text(R"({"vi\new": "top\nbottom", "view": "a\u2028b"})", "k.json");
  ObjectReader r(j, "k.json");
  const auto choice = error_of([&] { r.choice("view", {"body", "space"}); });
  EXPECT_TRUE(one_line(choice)) << choice;
  EXPECT_NE(choice.find("a\\u2028b"), std::string::npos) << choice;
  const auto unknown = error_of([&] { r.finish(); });
  EXPECT_TRUE(one_line(unknown)) << unknown;
  EXPECT_NE(unknown.find("key 'vi\\new': unknown key"), std::string::npos) << unknown;
}

TEST(JsonReader, LargeIntegersDoNotWrapInMessages) {
  const auto j = parse_json_text(
      R"({"width": 18446744073709551615, "height": -9223372036854775808})", "i.json");
  ObjectReader r(j, "i.json");
  const auto width = error_of([&] { r.integer("width", 16, 8192); });
  EXPECT_NE(width.find("got the integer 18446744073709551615"), std::string::npos) << width;
  const auto height = error_of([&] { r.integer("height", 16, 8192); });
  EXPECT_NE(height.find("got the integer -9223372036854775808"), std::string::npos) << height;
}

TEST(JsonReader, PrintableEscapesControlsAndBadUtf8AndCutsLongText) {
  EXPECT_EQ(printable("a\nb\tc\x01"), "a\\nb\\tc\\u0001");
  EXPECT_EQ(printable("\xff\xfe ok"), "\\xff\\xfe ok");
  EXPECT_EQ(printable("caf\xc3\xa9"), "caf\xc3\xa9");  // UTF-8 passes through
  EXPECT_EQ(printable("\xc2\x85"), "\\u0085");         // NEL, a C1 line break
  const auto cut = printable(std::string(1000, 'y'), 10);
  EXPECT_EQ(cut, "yyyyyyyyyy... (1000 bytes)");
  // A multi-byte character is never split.
  const auto accents = printable("\xc3\xa9\xc3\xa9\xc3\xa9", 3);
  EXPECT_EQ(accents, "\xc3\xa9\xc3\xa9... (6 bytes)");
}

using JsonFile = epviz::test::TempDirTest;

TEST_F(JsonFile, AnEndlessDeviceIsReadOnlyUpToTheLimit) {
  const auto message = error_of([] { epviz::io::read_json_file("/dev/zero"); });
  EXPECT_NE(message.find("/dev/zero: larger than 16 MiB"), std::string::npos) << message;
}

TEST_F(JsonFile, AFileOverTheLimitIsRefusedAndOneAtItIsRead) {
  const auto at_limit = dir_ / "at.json";
  {
    std::ofstream out(at_limit);
    out << "{}" << std::string(epviz::io::max_json_file_bytes - 2, ' ');
  }
  EXPECT_NO_THROW(epviz::io::read_json_file(at_limit));
  std::ofstream(at_limit, std::ios::app) << ' ';
  const auto message = error_of([&] { epviz::io::read_json_file(at_limit); });
  EXPECT_NE(message.find("at.json: larger than 16 MiB"), std::string::npos) << message;
}

TEST_F(JsonFile, ADirectorySaysSo) {
  const auto message = error_of([&] { epviz::io::read_json_file(dir_); });
  EXPECT_NE(message.find(": is a directory, not a job file"), std::string::npos) << message;
}

TEST_F(JsonFile, AMissingFileSaysWhy) {
  const auto message = error_of([&] { epviz::io::read_json_file(dir_ / "none.json"); });
  EXPECT_NE(message.find("none.json: cannot open the file for reading (No such file"),
            std::string::npos)
      << message;
}

// The file is opened without waiting for a writer, and then waits for one:
// a generator that opens the pipe late and writes in pieces is read whole.
TEST_F(JsonFile, APipeWhoseWriterComesLateIsReadWhole) {
  const auto fifo = dir_ / "late.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The writer opens only once the reader has the pipe open (before that a
  // non-blocking open for writing fails), and writes its second piece only
  // once the reader has drained the first (FIONREAD counts what is unread).
  std::thread writer([&] {
    int fd = -1;
    const bool opened = epviz::test::eventually(
        [&] { return (fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK)) >= 0; },
        std::chrono::seconds(10));
    if (!opened) return;
    const std::string first = "{\"a\": ", second = "[1, 2]}";
    const bool wrote_first = ::write(fd, first.data(), first.size()) == ssize_t(first.size());
    const bool drained =
        wrote_first && epviz::test::eventually(
                           [&] {
                             int unread = -1;
                             return ::ioctl(fd, FIONREAD, &unread) == 0 && unread == 0;
                           },
                           std::chrono::seconds(10));
    if (drained) (void)!::write(fd, second.data(), second.size());
    ::close(fd);
  });
  json read;
  EXPECT_NO_THROW(read = epviz::io::read_json_file(fifo));
  // Should the reader have given up first, a reader here lets the writer end.
  const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  writer.join();
  if (fd >= 0) ::close(fd);
  EXPECT_EQ(read, json::parse(R"({"a": [1, 2]})"));
}

TEST_F(JsonFile, AFileNameWithANewlineStaysOnOneLine) {
  const auto path = dir_ / "bad\nname.json";
  std::ofstream(path) << "[]";
  const auto message = error_of([&] { epviz::io::read_json_file(path); });
  EXPECT_TRUE(one_line(message)) << message;
  EXPECT_NE(message.find("bad\\nname.json"), std::string::npos) << message;
}

}  // namespace
