#include "io/json_line.hpp"

#include <charconv>
#include <cmath>

namespace epviz::io {

void JsonLine::separate() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (!first_.empty()) {
    if (!first_.back()) out_ += ',';
    first_.back() = false;
  }
}

void JsonLine::open(char bracket) {
  separate();
  out_ += bracket;
  first_.push_back(true);
}

void JsonLine::close(char bracket) {
  out_ += bracket;
  first_.pop_back();
}

JsonLine& JsonLine::begin_object() {
  open('{');
  return *this;
}

JsonLine& JsonLine::end_object() {
  close('}');
  return *this;
}

JsonLine& JsonLine::begin_array() {
  open('[');
  return *this;
}

JsonLine& JsonLine::end_array() {
  close(']');
  return *this;
}

JsonLine& JsonLine::key(std::string_view k) {
  value(k);
  out_ += ':';
  after_key_ = true;
  return *this;
}

JsonLine& JsonLine::value(double x) {
  if (!std::isfinite(x)) return null();
  separate();
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  const std::string_view text(buf, std::size_t(r.ptr - buf));
  out_ += text;
  // "10" would read back as an integer: a double keeps its fraction.
  if (text.find_first_of(".e") == std::string_view::npos) out_ += ".0";
  return *this;
}

JsonLine& JsonLine::value(long x) {
  separate();
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out_.append(buf, r.ptr);
  return *this;
}

JsonLine& JsonLine::value(bool x) {
  separate();
  out_ += x ? "true" : "false";
  return *this;
}

JsonLine& JsonLine::value(std::string_view s) {
  separate();
  out_ += '"';
  for (const char c : s) {
    switch (c) {
      case '"': out_ += "\\\""; break;
      case '\\': out_ += "\\\\"; break;
      case '\n': out_ += "\\n"; break;
      case '\r': out_ += "\\r"; break;
      case '\t': out_ += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          static constexpr char hex[] = "0123456789abcdef";
          out_ += "\\u00";
          out_ += hex[(c >> 4) & 0xf];
          out_ += hex[c & 0xf];
        } else {
          out_ += c;
        }
    }
  }
  out_ += '"';
  return *this;
}

JsonLine& JsonLine::null() {
  separate();
  out_ += "null";
  return *this;
}

JsonLine& JsonLine::raw(std::string_view json) {
  separate();
  out_ += json;
  return *this;
}

JsonLine& JsonLine::triple(double a, double b, double c) {
  return begin_array().value(a).value(b).value(c).end_array();
}

}  // namespace epviz::io
