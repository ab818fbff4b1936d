#pragma once
// Ensembles of the direct Euler–Poisson system (direct.hpp): many initial
// states integrated by the batch steppers (numerics/batch_driver.hpp), W lanes
// at a time, on the instruction set chosen at run time
// (numerics/simd_path.hpp). A trajectory's results do not depend on the batch:
// they are bitwise those of the scalar DOP853 / RK4 on it alone
// (docs/ensembles.md).
#include <optional>
#include <vector>

#include "numerics/batch_driver.hpp"
#include "numerics/simd_path.hpp"
#include "physics/body.hpp"

namespace epviz::sim {

enum class BatchMethod { dop853, rk4 };

struct DirectBatchSettings {
  BatchMethod method = BatchMethod::dop853;
  numerics::AdaptiveOptions adaptive;  // dop853
  numerics::BatchRk4Options rk4;       // rk4
  // Empty: numerics::chosen_simd_path() (EPVIZ_SIMD, else the widest).
  std::optional<numerics::SimdPath> path;
  int width = 0;  // lanes: 1, 2, 4 or 8; 0: default_batch_width(path)
  // dop853 only: each output's check, and the trajectories' starts and ends
  // (numerics/batch_driver.hpp), called with the task's id from the thread
  // integrating it.
  numerics::BatchOutputCheck<6> check;
  numerics::BatchEvents<6> events;
  // dop853 only: sees every accepted step and may look into its dense output
  // (numerics/batch_driver.hpp), from the thread integrating it.
  numerics::BatchStepHook<6> step_hook;
};

using DirectBatchTask = numerics::BatchTask<6>;
using DirectBatchResult = numerics::BatchResult<6>;

// The task from the initial state (Omega, gamma) at t = 0 to t_end.
DirectBatchTask direct_batch_task(const physics::InitialState& s, double t_end,
                                  std::vector<double> out_times = {});

// The lanes a path uses unless told: the fastest measured (docs/ensembles.md).
int default_batch_width(numerics::SimdPath path);

// One result per task, in order. Throws std::invalid_argument for bad tasks,
// options or width, and as numerics::parse_simd_path for EPVIZ_SIMD or a path
// this CPU lacks; a trajectory's own failure is in its result.
std::vector<DirectBatchResult> integrate_direct_batch(const physics::Body& body,
                                                      const std::vector<DirectBatchTask>& tasks,
                                                      const DirectBatchSettings& settings = {});

// The same, the tasks shared among `threads` threads (each running batches of
// W lanes on chunks taken in turn): the results are bitwise those of
// integrate_direct_batch. Bad input throws before any thread starts.
std::vector<DirectBatchResult> integrate_direct_batch_parallel(
    const physics::Body& body, const std::vector<DirectBatchTask>& tasks,
    const DirectBatchSettings& settings = {}, int threads = 2);

}  // namespace epviz::sim
