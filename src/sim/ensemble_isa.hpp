#pragma once
// The batch kernels of the direct system compiled for each instruction set,
// one unit each (direct_batch_scalar.cpp, _sse2, _avx2, _avx512), for every
// lane count the dispatcher (direct_batch.cpp) offers.
#include "numerics/batch_lanes.hpp"
#include "numerics/rk_tableaus.hpp"
#include "numerics/simd_path.hpp"
#include "physics/direct_rhs_batch.hpp"

namespace epviz::sim::batch_isa {

template <int W>
struct DirectKernelsOf {
  numerics::EmbeddedKernels<physics::DirectBatchSystem, W, numerics::Dop853Tableau> dop853;
  numerics::Rk4Kernel<physics::DirectBatchSystem, W> rk4;
};

struct DirectKernels {
  DirectKernelsOf<1> w1;
  DirectKernelsOf<2> w2;
  DirectKernelsOf<4> w4;
  DirectKernelsOf<8> w8;
};

extern const DirectKernels kScalar, kSse2, kAvx2, kAvx512;

// The kernels of `path`; throws std::invalid_argument when this CPU lacks it.
const DirectKernels& kernels_for(numerics::SimdPath path);

}  // namespace epviz::sim::batch_isa
