// The direct system's batch kernels for SSE2, 128-bit vectors (plain x86-64); the flags are set for
// this file alone in CMakeLists.txt, always with -ffp-contract=off.
#include "sim/ensemble_kernels.hpp"

namespace epviz::sim::batch_isa {
namespace {
struct Sse2Unit {};
}  // namespace

const DirectKernels kSse2 = direct_kernels<Sse2Unit>();

}  // namespace epviz::sim::batch_isa
