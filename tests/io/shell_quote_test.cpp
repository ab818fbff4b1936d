// io::shell_quote: plain words stay as they are, and every other word, read
// back by bash, is the same word again (spaces, quotes, the empty word and
// what a shell would expand).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/shell_quote.hpp"
#include "io/subprocess.hpp"

namespace epviz::io {
namespace {

// What bash makes of `line` as the arguments of printf '%s|'.
std::string as_bash_reads_it(const std::string& line) {
  const auto r = run_process({"bash", "-c", "printf '%s|' " + line});
  EXPECT_TRUE(r.status.success()) << line << ": " << r.status.describe() << " " << r.err;
  return r.out;
}

TEST(ShellQuote, PlainWordsAreUnchanged) {
  for (const std::string w :
       {"epviz", "/abs/a.sweep.json", "rows-1.jsonl", "--shard", "a=b,c:d", "x+y@50%"})
    EXPECT_EQ(shell_quote(w), w);
}

TEST(ShellQuote, OtherWordsAreQuoted) {
  EXPECT_EQ(shell_quote(""), "''");
  EXPECT_EQ(shell_quote("a b"), "'a b'");
  EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
}

TEST(ShellQuote, BashReadsEachWordBackAsItWas) {
  const std::vector<std::string> words = {"plain",     "two words",   "it's",           "",
                                          "''",        "\\'",         "$HOME *",        "a\"b",
                                          "tab\there", "line\nbreak", "`ls`; rm -rf x", "é ü"};
  std::string line, expected;
  for (const auto& w : words) {
    line += shell_quote(w) + " ";
    expected += w + "|";
  }
  EXPECT_EQ(as_bash_reads_it(line), expected);
}

}  // namespace
}  // namespace epviz::io
