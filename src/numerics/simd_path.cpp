#include "numerics/simd_path.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace epviz::numerics {

std::string_view name(SimdPath path) {
  switch (path) {
    case SimdPath::scalar: return "scalar";
    case SimdPath::sse2: return "sse2";
    case SimdPath::avx2: return "avx2";
    case SimdPath::avx512: return "avx512";
  }
  return "unknown";  // not reached: the switch lists every path
}

bool cpu_supports(SimdPath path) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  switch (path) {
    case SimdPath::scalar:
    case SimdPath::sse2: return true;  // part of x86-64
    case SimdPath::avx2: return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    case SimdPath::avx512:
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
  }
  return false;
#else
  // Elsewhere the vector paths are not built for their instruction sets.
  return path == SimdPath::scalar;
#endif
}

SimdPath widest_simd_path() {
  SimdPath widest = SimdPath::scalar;
  for (SimdPath p : kSimdPaths)
    if (cpu_supports(p)) widest = p;
  return widest;
}

SimdPath parse_simd_path(std::string_view value) {
  for (SimdPath p : kSimdPaths) {
    if (value != name(p)) continue;
    if (!cpu_supports(p))
      throw std::invalid_argument("EPVIZ_SIMD=" + std::string(value) +
                                  ": this CPU lacks that instruction set (widest available: " +
                                  std::string(name(widest_simd_path())) + ")");
    return p;
  }
  throw std::invalid_argument("EPVIZ_SIMD=" + std::string(value) +
                              ": unknown; allowed: scalar, sse2, avx2, avx512");
}

SimdPath chosen_simd_path() {
  const char* value = std::getenv("EPVIZ_SIMD");
  if (value == nullptr || *value == '\0') return widest_simd_path();
  return parse_simd_path(value);
}

std::string simd_path_report() {
  try {
    const char* value = std::getenv("EPVIZ_SIMD");
    const bool forced = value != nullptr && *value != '\0';
    return std::string(name(chosen_simd_path())) +
           (forced ? " (EPVIZ_SIMD)" : " (widest of this CPU)");
  } catch (const std::invalid_argument& e) {
    return std::string("none: ") + e.what();
  }
}

}  // namespace epviz::numerics
