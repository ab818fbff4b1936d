#include "sim/ensemble.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "numerics/batch_rk4.hpp"
#include "sim/ensemble_isa.hpp"

namespace epviz::sim {

DirectBatchTask direct_batch_task(const physics::InitialState& s, double t_end,
                                  std::vector<double> out_times) {
  DirectBatchTask task;
  task.t_end = t_end;
  for (int i = 0; i < 3; ++i) {
    task.x0[std::size_t(i)] = s.omega[i];
    task.x0[std::size_t(3 + i)] = s.gamma[i];
  }
  task.out_times = std::move(out_times);
  return task;
}

const batch_isa::DirectKernels& batch_isa::kernels_for(numerics::SimdPath path) {
  if (!numerics::cpu_supports(path)) numerics::parse_simd_path(numerics::name(path));  // throws
  switch (path) {
    case numerics::SimdPath::scalar: return batch_isa::kScalar;
    case numerics::SimdPath::sse2: return batch_isa::kSse2;
    case numerics::SimdPath::avx2: return batch_isa::kAvx2;
    case numerics::SimdPath::avx512: return batch_isa::kAvx512;
  }
  return batch_isa::kScalar;
}

int default_batch_width(numerics::SimdPath path) {
  switch (path) {
    case numerics::SimdPath::scalar: return 1;
    case numerics::SimdPath::sse2: return 2;
    case numerics::SimdPath::avx2: return 4;
    case numerics::SimdPath::avx512: return 8;
  }
  return 1;
}

namespace {

template <int W>
std::vector<DirectBatchResult> run(const physics::DirectBatchSystem& sys,
                                   const batch_isa::DirectKernelsOf<W>& kernels,
                                   const std::vector<DirectBatchTask>& tasks,
                                   const DirectBatchSettings& settings) {
  if (settings.method == BatchMethod::rk4) {
    if (settings.check || settings.events.started || settings.events.ended || settings.step_hook)
      throw std::invalid_argument("batch rk4: no output check, events or step hook (dop853 only)");
    return numerics::BatchRk4<physics::DirectBatchSystem, W>(sys, kernels.rk4, settings.rk4)
        .run(tasks);
  }
  return numerics::BatchEmbedded<physics::DirectBatchSystem, W, numerics::Dop853Tableau>(
             sys, kernels.dop853, settings.adaptive, settings.check, settings.events,
             settings.step_hook)
      .run(tasks);
}

}  // namespace

std::vector<DirectBatchResult> integrate_direct_batch(const physics::Body& body,
                                                      const std::vector<DirectBatchTask>& tasks,
                                                      const DirectBatchSettings& settings) {
  const numerics::SimdPath path = settings.path ? *settings.path : numerics::chosen_simd_path();
  const batch_isa::DirectKernels& k = batch_isa::kernels_for(path);
  const physics::DirectBatchSystem sys = physics::DirectBatchSystem::of(body);
  switch (settings.width == 0 ? default_batch_width(path) : settings.width) {
    case 1: return run<1>(sys, k.w1, tasks, settings);
    case 2: return run<2>(sys, k.w2, tasks, settings);
    case 4: return run<4>(sys, k.w4, tasks, settings);
    case 8: return run<8>(sys, k.w8, tasks, settings);
  }
  throw std::invalid_argument("batch width " + std::to_string(settings.width) +
                              ": allowed are 1, 2, 4 and 8 lanes (or 0 for the path's own)");
}

}  // namespace epviz::sim
