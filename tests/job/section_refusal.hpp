#pragma once
// A small render job whose "section" is `section` (JSON text), given to
// `epviz render`: it must be refused before any work, naming `named`.
#include <string>

#include "support/cli.hpp"

namespace epviz::test {

inline void expect_section_refused(const std::string& section, const std::string& named) {
  SCOPED_TRACE(section);
  TempDir dir;
  std::string job = R"({"simulation": {"case": "kovalevskaya", "t_end": 2}, "section": )";
  job += section;
  job += R"(, "width": 64, "height": 48, "fps": 2, "duration": 1, "output": {"dir": ")";
  job += (dir / "out").string();
  job += R"(", "format": "png"}})";
  expect_render_refused(dir, job, "--quiet", dir / "out", named);
}

}  // namespace epviz::test
