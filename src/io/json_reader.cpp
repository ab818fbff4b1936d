#include "io/json_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <set>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/printable.hpp"

namespace epviz::io {
namespace {

using Json = nlohmann::json;

// File names may hold any byte but '/' and NUL; long ones are legitimate.
std::string file_name(const std::string& file) { return printable(file, 1000); }

// Builds the value of a JSON text as Json::parse does (from the parser's SAX
// events), and on the way knows where the parser is, as a key path
// ("camera.azimuth", "jobs[2]"), so that errors the parser raises before a
// value exists can still name its key; refuses a key given twice in one
// object and nesting past the limit. Linear in the text: Json::parse with a
// callback, which did this before, scans an array's elements for discarded
// values at the end of each object in it (nlohmann/json 3.11), quadratic in
// the objects of one array (80 s for a 1.2 MB job).
class StrictBuilder {
 public:
  explicit StrictBuilder(std::string file) : file_(std::move(file)) {}

  bool null() { return put(nullptr); }
  bool boolean(bool v) { return put(v); }
  bool number_integer(Json::number_integer_t v) { return put(v); }
  bool number_unsigned(Json::number_unsigned_t v) { return put(v); }
  bool number_float(Json::number_float_t v, const Json::string_t&) { return put(v); }
  bool string(Json::string_t& v) { return put(std::move(v)); }
  bool binary(Json::binary_t& v) { return put(Json::binary(std::move(v))); }
  bool start_object(std::size_t) { return open(true); }
  bool start_array(std::size_t) { return open(false); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(Json::string_t& k) {
    auto& top = levels_.back();
    top.key = k;
    if (!top.keys.insert(k).second)
      throw BadInput(file_name(file_) + ": " + at() +
                     "given twice in one object (only one is allowed)");
    return true;
  }
  // The parser's own error (its type kept, for the caller's catch).
  template <class Exception>
  bool parse_error(std::size_t, const std::string&, const Exception& e) {
    throw e;
  }

  Json take() { return std::move(root_); }

  // "key 'a.b': ", or "" at the top level; deeper than `max_levels`, "key 'a[0]...': ".
  std::string at(std::size_t max_levels = std::size_t(max_json_depth)) const {
    std::string path;
    for (const auto& l : levels_) {
      if (max_levels-- == 0) {
        path += "...";
        break;
      }
      if (l.object)
        path += (path.empty() ? "" : ".") + l.key;
      else
        path += "[" + std::to_string(l.index) + "]";
    }
    return path.empty() ? "" : "key '" + printable(path, 200) + "': ";
  }

 private:
  struct Level {
    bool object;
    Json* value;                 // the array or object being filled
    std::set<std::string> keys;  // objects: the keys seen so far
    std::string key;             // objects: the key whose value is being read
    std::size_t index = 0;       // arrays: the element being read
  };

  // Puts `v` where the parser is and returns where it went. A container's
  // address stays valid while it is open: its parent gets no other element
  // until it closes (a map's nodes and a vector's last element alike).
  Json* place(Json&& v) {
    if (levels_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Level& top = levels_.back();
    if (top.object) {
      Json& slot = (*top.value)[top.key];
      slot = std::move(v);
      return &slot;
    }
    top.value->push_back(std::move(v));
    return &top.value->back();
  }
  bool put(Json&& v) {
    place(std::move(v));
    next_element();
    return true;
  }
  bool open(bool object) {
    if (levels_.size() >= std::size_t(max_json_depth))
      throw BadInput(file_name(file_) + ": " + at(2) + "nested deeper than " +
                     std::to_string(max_json_depth) + " levels of arrays and objects");
    Json* value = place(object ? Json::object() : Json::array());
    levels_.push_back({object, value, {}, {}, 0});
    return true;
  }
  bool close() {
    levels_.pop_back();
    next_element();
    return true;
  }
  void next_element() {
    if (!levels_.empty() && !levels_.back().object) ++levels_.back().index;
  }

  std::string file_;
  Json root_;
  std::vector<Level> levels_;
};

// "1e400" from the library's "number overflow parsing '1e400'".
std::string overflowing_token(const std::string& what) {
  const auto open = what.find("parsing '");
  const auto close = what.rfind('\'');
  if (open == std::string::npos || close == std::string::npos || close <= open + 9) return "";
  return " " + printable(what.substr(open + 9, close - open - 9), 40);
}

// The value itself, cut off once `out` reaches `limit` bytes. Each level of
// nesting adds at least one byte, so the recursion is as deep as `limit` at most.
void preview(const Json& v, std::string& out, std::size_t limit) {
  if (out.size() >= limit) return;
  switch (v.type()) {
    case Json::value_t::array: {
      out += '[';
      bool first = true;
      for (const auto& x : v) {
        if (out.size() >= limit) return;
        if (!first) out += ", ";
        first = false;
        preview(x, out, limit);
      }
      out += ']';
      break;
    }
    case Json::value_t::object: {
      out += '{';
      bool first = true;
      for (auto it = v.begin(); it != v.end(); ++it) {
        if (out.size() >= limit) return;
        if (!first) out += ", ";
        first = false;
        out += '"' + printable(it.key(), limit - out.size()) + "\": ";
        preview(it.value(), out, limit);
      }
      out += '}';
      break;
    }
    case Json::value_t::string:
      out += '"' + printable(v.get_ref<const std::string&>(), limit - out.size()) + '"';
      break;
    default: out += v.dump(); break;  // a number, true, false or null: short
  }
}

}  // namespace

Json parse_json_text(std::string_view text, const std::string& file) {
  StrictBuilder tracker(file);
  Json j;
  try {
    Json::sax_parse(text.begin(), text.end(), &tracker);
    j = tracker.take();
  } catch (const Json::parse_error& e) {
    // e.byte is the offset of the failure; turn it into line:column for the user.
    std::size_t line = 1, col = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    throw BadInput(file_name(file) + ":" + std::to_string(line) + ":" + std::to_string(col) +
                   ": not valid JSON");
  } catch (const Json::out_of_range& e) {
    // The one range error of the parser: a number too large for a double.
    throw BadInput(file_name(file) + ": " + tracker.at() + "the number" +
                   overflowing_token(e.what()) +
                   " is out of range (a double holds magnitudes up to about 1.8e308)");
  } catch (const Json::exception& e) {
    throw BadInput(file_name(file) + ": not valid JSON (" + printable(e.what(), 120) + ")");
  }
  if (!j.is_object()) throw BadInput(file_name(file) + ": the job must be a JSON object {...}");
  return j;
}

Json read_json_file(const std::filesystem::path& path) {
  const std::string file = path.string();
  // Opened without blocking: opening a named pipe otherwise waits, for ever,
  // for a writer to appear. Each wait for data is bounded instead.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
    throw BadInput(file_name(file) + ": cannot open the file for reading (" + std::strerror(errno) +
                   ")");
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) == 0 && S_ISDIR(info.st_mode))
    throw BadInput(file_name(file) + ": is a directory, not a job file");
  // Read at most one byte past the limit: /dev/zero or an endless pipe ends here.
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    pollfd ready{fd, POLLIN, 0};
    const int polled = ::poll(&ready, 1, json_file_wait_seconds * 1000);
    if (polled < 0 && errno == EINTR) continue;
    if (polled == 0)
      throw BadInput(file_name(file) + ": nothing to read for " +
                     std::to_string(json_file_wait_seconds) +
                     " s (a pipe nobody writes to?); give a regular file");
    const ssize_t got = polled < 0 ? -1 : ::read(fd, buffer, sizeof buffer);
    if (got < 0 && (errno == EAGAIN || errno == EINTR)) continue;
    if (got < 0)
      throw BadInput(file_name(file) + ": cannot read the file (" + std::strerror(errno) + ")");
    if (got == 0) break;
    text.append(buffer, std::size_t(got));
    if (text.size() > max_json_file_bytes)
      throw BadInput(file_name(file) + ": larger than " +
                     std::to_string(max_json_file_bytes >> 20) + " MiB, the limit for a job file");
  }
  return parse_json_text(text, file);
}

std::string describe(const Json& value) {
  constexpr std::size_t limit = 60;
  std::string text;
  preview(value, text, limit);
  if (text.size() > limit) text = text.substr(0, limit);
  const bool cut = text.size() >= limit;
  // Don't end the cut inside a UTF-8 sequence.
  while (cut && !text.empty() && (static_cast<unsigned char>(text.back()) & 0xc0) == 0x80)
    text.pop_back();
  if (cut && !text.empty() && static_cast<unsigned char>(text.back()) >= 0xc0) text.pop_back();
  if (cut) text += "...";
  switch (value.type()) {
    case Json::value_t::array: return "an array " + text;
    case Json::value_t::object: return "an object " + text;
    case Json::value_t::string: return "a string " + text;
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned: return "the integer " + text;
    case Json::value_t::number_float: return "the number " + text;
    default: return text;  // true, false, null
  }
}

ObjectReader::ObjectReader(const Json& object, std::string file, std::string path)
    : object_(&object), file_(std::move(file)), path_(std::move(path)) {}

std::string ObjectReader::where(const std::string& key) const {
  return file_name(file_) + ": key '" + printable(path_.empty() ? key : path_ + "." + key, 200) +
         "'";
}

void ObjectReader::fail(const std::string& key, const std::string& what) const {
  throw BadInput(where(key) + ": " + what);
}

bool ObjectReader::has(const std::string& key) const { return object_->contains(key); }

std::optional<std::string> ObjectReader::peek_string(const std::string& key) const {
  auto it = object_->find(key);
  if (it == object_->end() || !it->is_string()) return std::nullopt;
  return it->get<std::string>();
}

void ObjectReader::remember(const std::string& key) {
  if (std::find(read_.begin(), read_.end(), key) == read_.end()) read_.push_back(key);
}

const Json* ObjectReader::get(const std::string& key) {
  remember(key);
  auto it = object_->find(key);
  return it == object_->end() ? nullptr : &*it;
}

std::optional<double> ObjectReader::number(const std::string& key) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_number()) fail(key, "expected a number, got " + describe(*v));
  const double x = v->get<double>();
  if (!std::isfinite(x)) fail(key, "expected a finite number");
  return x;
}

std::optional<double> ObjectReader::positive_number(const std::string& key) {
  auto x = number(key);
  if (x && !(*x > 0.0)) fail(key, "expected a positive number, got " + describe(object_->at(key)));
  return x;
}

std::optional<double> ObjectReader::number_in(const std::string& key, double min_value,
                                              double max_value, const std::string& allowed) {
  auto x = number(key);
  if (x && !(*x >= min_value && *x <= max_value))
    fail(key, "expected " + allowed + ", got " + describe(object_->at(key)));
  return x;
}

std::optional<long> ObjectReader::integer(const std::string& key, long min_value, long max_value) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  const std::string expected =
      "expected an integer from " + std::to_string(min_value) + " to " + std::to_string(max_value);
  if (!v->is_number_integer()) fail(key, expected + ", got " + describe(*v));
  // An unsigned value past the largest long must not wrap around to a negative one.
  const bool in_range =
      v->is_number_unsigned()
          ? max_value >= 0 && v->get<std::uint64_t>() <= std::uint64_t(max_value) &&
                (min_value <= 0 || v->get<std::uint64_t>() >= std::uint64_t(min_value))
          : v->get<long>() >= min_value && v->get<long>() <= max_value;
  if (!in_range) fail(key, expected + ", got " + describe(*v));
  return v->get<long>();
}

std::optional<bool> ObjectReader::boolean(const std::string& key) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_boolean()) fail(key, "expected true or false, got " + describe(*v));
  return v->get<bool>();
}

std::optional<std::string> ObjectReader::string(const std::string& key) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_string()) fail(key, "expected a string, got " + describe(*v));
  return v->get<std::string>();
}

std::optional<std::string> ObjectReader::choice(const std::string& key,
                                                const std::vector<std::string>& allowed) {
  auto s = string(key);
  if (!s) return s;
  for (const auto& a : allowed)
    if (a == *s) return s;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  fail(key, "'" + printable(*s) + "' is not one of: " + list);
}

std::optional<std::array<double, 3>> ObjectReader::vec3(const std::string& key) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_array() || v->size() != 3)
    fail(key, "expected an array of 3 numbers, got " + describe(*v));
  std::array<double, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!(*v)[i].is_number()) fail(key, "expected an array of 3 numbers, got " + describe(*v));
    out[i] = (*v)[i].get<double>();
  }
  return out;
}

std::optional<ObjectReader> ObjectReader::object(const std::string& key) {
  const auto* v = get(key);
  if (!v) return std::nullopt;
  if (!v->is_object()) fail(key, "expected an object {...}, got " + describe(*v));
  return ObjectReader(*v, file_, path_.empty() ? key : path_ + "." + key);
}

void ObjectReader::finish() const {
  for (auto it = object_->begin(); it != object_->end(); ++it) {
    if (std::find(read_.begin(), read_.end(), it.key()) != read_.end()) continue;
    std::vector<std::string> keys = read_;
    std::sort(keys.begin(), keys.end());
    std::string allowed;
    for (const auto& k : keys) allowed += (allowed.empty() ? "" : ", ") + k;
    fail(it.key(), "unknown key (allowed here: " + allowed + ")");
  }
}

}  // namespace epviz::io
