// The direct system's batch kernels for AVX2 with FMA enabled, 256-bit vectors (-mavx2 -mfma); the
// flags are set for this file alone in CMakeLists.txt, always with -ffp-contract=off.
#include "sim/ensemble_kernels.hpp"

namespace epviz::sim::batch_isa {
namespace {
struct Avx2Unit {};
}  // namespace

const DirectKernels kAvx2 = direct_kernels<Avx2Unit>();

}  // namespace epviz::sim::batch_isa
