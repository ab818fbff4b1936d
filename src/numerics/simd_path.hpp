#pragma once
// The vector instruction sets the batch steppers are compiled for, which of
// them this CPU runs, and the one chosen: the widest the CPU has, unless the
// environment variable EPVIZ_SIMD names one (scalar, sse2, avx2, avx512).
//
// Every path computes the same IEEE operations in the same order, so the
// choice changes the speed only, never a result (docs/ensembles.md).
#include <array>
#include <string>
#include <string_view>

namespace epviz::numerics {

enum class SimdPath {
  scalar,  // one lane at a time
  sse2,    // 128-bit vectors (every x86-64 CPU)
  avx2,    // 256-bit vectors (AVX2 with FMA)
  avx512,  // 512-bit vectors (AVX-512 F and DQ)
};

inline constexpr std::array<SimdPath, 4> kSimdPaths{SimdPath::scalar, SimdPath::sse2,
                                                    SimdPath::avx2, SimdPath::avx512};

// "scalar", "sse2", "avx2", "avx512".
std::string_view name(SimdPath path);

// Whether this CPU can run the path.
bool cpu_supports(SimdPath path);

// The widest path this CPU supports.
SimdPath widest_simd_path();

// The path named by `value` (an EPVIZ_SIMD value). Throws std::invalid_argument
// with a one-line message naming EPVIZ_SIMD when the name is unknown or the CPU
// lacks the path.
SimdPath parse_simd_path(std::string_view value);

// EPVIZ_SIMD's path when the variable is set and not empty, else the widest
// path of this CPU. Throws as parse_simd_path does.
SimdPath chosen_simd_path();

// One line for `epviz --version`: the chosen path and why ("avx2 (widest of
// this CPU)", "sse2 (EPVIZ_SIMD)"), or what is wrong with EPVIZ_SIMD. Never throws.
std::string simd_path_report();

}  // namespace epviz::numerics
