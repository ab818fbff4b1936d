#pragma once
// Included by each ensemble_<isa>.cpp only: the kernel table of that unit,
// instantiated with a tag type of the unit's anonymous namespace
// (numerics/batch_kernel.hpp says why).
#include "numerics/batch_kernel.hpp"
#include "sim/ensemble_isa.hpp"

namespace epviz::sim::batch_isa {

template <int W, class Tag>
constexpr DirectKernelsOf<W> direct_kernels_of() {
  using Sys = physics::DirectBatchSystem;
  return {numerics::batch::EmbeddedKernel<Sys, W, numerics::Dop853Tableau, Tag>::table,
          numerics::batch::Rk4KernelImpl<Sys, W, Tag>::table};
}

template <class Tag>
constexpr DirectKernels direct_kernels() {
  return {direct_kernels_of<1, Tag>(), direct_kernels_of<2, Tag>(), direct_kernels_of<4, Tag>(),
          direct_kernels_of<8, Tag>()};
}

}  // namespace epviz::sim::batch_isa
