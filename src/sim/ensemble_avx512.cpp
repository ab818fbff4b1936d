// The direct system's batch kernels for AVX-512 F and DQ, 512-bit vectors (-mavx512f -mavx512dq);
// the flags are set for this file alone in CMakeLists.txt, always with -ffp-contract=off.
#include "sim/ensemble_kernels.hpp"

namespace epviz::sim::batch_isa {
namespace {
struct Avx512Unit {};
}  // namespace

const DirectKernels kAvx512 = direct_kernels<Avx512Unit>();

}  // namespace epviz::sim::batch_isa
