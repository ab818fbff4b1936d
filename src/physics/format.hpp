#pragma once
// Number formatting for messages a user reads: the shortest text that reads
// back as the same double ("1.5", "0.1", "1e-20").
#include <Eigen/Core>
#include <charconv>
#include <string>

namespace epviz::physics::detail {

inline std::string num(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

inline std::string vec(const Eigen::Vector3d& v) {
  return "(" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + ")";
}

}  // namespace epviz::physics::detail
