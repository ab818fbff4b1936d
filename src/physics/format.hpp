#pragma once
// Number formatting for messages a user reads: num() echoes a number the user
// gave as the shortest text that reads back as the same double ("1.5", "0.1").
#include <Eigen/Core>
#include <charconv>
#include <cstdio>
#include <string>

namespace epviz::physics::detail {

inline std::string num(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// A computed value, to 12 significant digits ("0.3", not "0.29999999999999993").
inline std::string approx(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 12);
  return std::string(buf, r.ptr);
}

inline std::string vec(const Eigen::Vector3d& v) {
  std::string s(1, '(');  // appended piecewise (GCC 12 warns on "literal" + string&&)
  s += num(v.x());
  s += ", ";
  s += num(v.y());
  s += ", ";
  s += num(v.z());
  s += ')';
  return s;
}

// A computed vector for display, to `digits` significant digits: "(0.5, 1, 2)".
inline std::string vec(const Eigen::Vector3d& v, int digits) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%.*g, %.*g, %.*g)", digits, v.x(), digits, v.y(), digits, v.z());
  return buf;
}

}  // namespace epviz::physics::detail
