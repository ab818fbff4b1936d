#include "io/printable.hpp"

#include <cstdio>

namespace epviz::io {
namespace {

// The length of the valid UTF-8 sequence at the start of `s`, or 0.
std::size_t utf8_length(std::string_view s) {
  const auto b = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
  const unsigned char c = b(0);
  std::size_t n = 0;
  unsigned long code = 0;
  if (c >= 0xc2 && c <= 0xdf) {
    n = 2;
    code = c & 0x1f;
  } else if (c >= 0xe0 && c <= 0xef) {
    n = 3;
    code = c & 0x0f;
  } else if (c >= 0xf0 && c <= 0xf4) {
    n = 4;
    code = c & 0x07;
  } else {
    return 0;
  }
  if (s.size() < n) return 0;
  for (std::size_t i = 1; i < n; ++i) {
    if ((b(i) & 0xc0) != 0x80) return 0;
    code = (code << 6) | (b(i) & 0x3f);
  }
  // Overlong forms, surrogates and code points past U+10FFFF are not UTF-8.
  if ((n == 3 && code < 0x800) || (n == 4 && (code < 0x10000 || code > 0x10ffff)) ||
      (code >= 0xd800 && code <= 0xdfff))
    return 0;
  return n;
}

// Code points that end or break a line or move the cursor on a terminal.
bool is_control(unsigned long code) {
  return code < 0x20 || (code >= 0x7f && code <= 0x9f) || code == 0x2028 || code == 0x2029;
}

unsigned long decode(std::string_view s, std::size_t n) {
  if (n == 1) return static_cast<unsigned char>(s[0]);
  unsigned long code = static_cast<unsigned char>(s[0]) & (0xff >> (n + 1));
  for (std::size_t i = 1; i < n; ++i)
    code = (code << 6) | (static_cast<unsigned char>(s[i]) & 0x3f);
  return code;
}

std::string escaped(unsigned long code) {
  switch (code) {
    case '\n': return "\\n";
    case '\r': return "\\r";
    case '\t': return "\\t";
    default: break;
  }
  char buf[16];
  std::snprintf(buf, sizeof buf, "\\u%04lx", code);
  return buf;
}

}  // namespace

std::string printable(std::string_view text, std::size_t max_bytes) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size() && out.size() < max_bytes) {
    const auto c = static_cast<unsigned char>(text[i]);
    const std::size_t n = c < 0x80 ? 1 : utf8_length(text.substr(i));
    if (n == 0) {  // not UTF-8: the byte itself
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
      ++i;
      continue;
    }
    const unsigned long code = decode(text.substr(i), n);
    if (is_control(code))
      out += escaped(code);
    else
      out.append(text.substr(i, n));
    i += n;
  }
  if (i < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string quoted(std::string_view text, std::size_t max_bytes) {
  std::string out(1, '\'');
  out += printable(text, max_bytes);
  out += '\'';
  return out;
}

}  // namespace epviz::io
