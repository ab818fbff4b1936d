#pragma once
// Typed, strict reading of JSON job files: every error names the file, the key
// path and what is allowed, and keys nobody asked for are errors (a typo must
// not pass silently). Hostile files are errors too, not crashes: a file is read
// up to a size limit, nesting is bounded, a key given twice is refused, and
// values are quoted in messages by type and a short prefix, on one line.
#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "io/bad_input.hpp"

namespace epviz::io {

// Job files are a few kilobytes; the limit keeps /dev/zero or a runaway
// generator from filling the memory.
inline constexpr std::size_t max_json_file_bytes = std::size_t{16} << 20;
// Jobs nest three levels deep; the limit keeps a hostile file from reaching
// the recursion of whatever walks the value later.
inline constexpr int max_json_depth = 64;

// A pipe (a named one nobody opened for writing, or a stalled generator) may
// never deliver: reading gives up after this long without a byte.
inline constexpr int json_file_wait_seconds = 5;

// Reads and parses a whole file (at most max_json_file_bytes and with no wait
// for data longer than json_file_wait_seconds, so a device or a pipe is not
// read forever); the root must be an object. Errors name the file
// and, for a syntax error, the line and column.
nlohmann::json read_json_file(const std::filesystem::path& path);
// The same for text already read; `file` names it in messages.
nlohmann::json parse_json_text(std::string_view text, const std::string& file);

// A JSON value for an error message: its type and a short prefix of it, on
// one line whatever its size, depth or content ("an array [[[[[...").
std::string describe(const nlohmann::json& value);

// Reads the members of one JSON object. Call finish() after the last get to
// reject unknown keys.
class ObjectReader {
 public:
  // `path` is the key path of this object ("" for the root); `file` is for messages.
  ObjectReader(const nlohmann::json& object, std::string file, std::string path = "");

  bool has(const std::string& key) const;
  // The string at `key` without marking it read (nullopt if absent or not a string).
  std::optional<std::string> peek_string(const std::string& key) const;
  // Marks a key as handled by the caller.
  void mark_read(const std::string& key) { remember(key); }
  // The raw value (nullptr if absent), marked read.
  const nlohmann::json* raw(const std::string& key) { return get(key); }
  std::optional<double> number(const std::string& key);
  std::optional<double> positive_number(const std::string& key);
  // A number from `min_value` to `max_value`; `allowed` words the range for the message.
  std::optional<double> number_in(const std::string& key, double min_value, double max_value,
                                  const std::string& allowed);
  std::optional<long> integer(const std::string& key, long min_value, long max_value);
  std::optional<bool> boolean(const std::string& key);
  std::optional<std::string> string(const std::string& key);
  // A string from a closed set of values.
  std::optional<std::string> choice(const std::string& key,
                                    const std::vector<std::string>& allowed);
  std::optional<std::array<double, 3>> vec3(const std::string& key);
  std::optional<ObjectReader> object(const std::string& key);

  // Throws BadInput naming the first key that was never read.
  void finish() const;

  // "file: key 'a.b'" for messages about a value after it was read.
  std::string where(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

 private:
  const nlohmann::json* get(const std::string& key);
  void remember(const std::string& key);

  const nlohmann::json* object_;
  std::string file_;
  std::string path_;
  // The keys asked for: a few dozen at most, where a search of a vector
  // costs less than a tree's allocations (a sweep reads once per point).
  std::vector<std::string> read_;
};

}  // namespace epviz::io
