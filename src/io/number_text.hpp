#pragma once
// A number in a figure's caption, a report line or a recommendation: printf's
// %g with `digits` significant digits ("0.0017", "1e-13").
#include <cstdio>
#include <string>

namespace epviz::io {

inline std::string number_text(double v, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace epviz::io
