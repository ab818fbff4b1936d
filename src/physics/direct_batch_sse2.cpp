// The direct system's batch kernels for SSE2, 128-bit vectors (plain x86-64); the flags are set for
// this file alone in CMakeLists.txt, always with -ffp-contract=off.
#include "physics/direct_batch_kernels.hpp"

namespace epviz::physics::batch_isa {
namespace {
struct Sse2Unit {};
}  // namespace

const DirectKernels kSse2 = direct_kernels<Sse2Unit>();

}  // namespace epviz::physics::batch_isa
