// The direct system's batch kernels for no vector instructions (built with -fno-tree-vectorize);
// the flags are set for this file alone in CMakeLists.txt, always with -ffp-contract=off.
#include "sim/ensemble_kernels.hpp"

namespace epviz::sim::batch_isa {
namespace {
struct ScalarUnit {};
}  // namespace

const DirectKernels kScalar = direct_kernels<ScalarUnit>();

}  // namespace epviz::sim::batch_isa
