#pragma once
// EPVIZ_SIMD set for a scope (numerics/simd_path.hpp reads it at each
// choice), and put back as it was.
#include <cstdlib>
#include <string>

namespace epviz::test {

class ScopedSimdEnv {
 public:
  explicit ScopedSimdEnv(const char* value) {
    if (const char* old = std::getenv("EPVIZ_SIMD")) old_ = old;
    ::setenv("EPVIZ_SIMD", value, 1);
  }
  ~ScopedSimdEnv() {
    if (old_.empty())
      ::unsetenv("EPVIZ_SIMD");
    else
      ::setenv("EPVIZ_SIMD", old_.c_str(), 1);
  }
  ScopedSimdEnv(const ScopedSimdEnv&) = delete;
  ScopedSimdEnv& operator=(const ScopedSimdEnv&) = delete;

 private:
  std::string old_;
};

}  // namespace epviz::test
