#pragma once
// What the C++ peers share: the state they integrate (physics::DirectSystem on
// plain arrays, the libraries' state type), the counted right-hand side, and
// the outcome of one run.
#include <algorithm>
#include <array>
#include <string>

#include "physics/direct.hpp"

namespace epviz::study::peers {

// DirectSystem::rhs on plain arrays, counting calls.
struct CountingRhs {
  const physics::DirectSystem* sys;
  long* count;
  void operator()(const double* x, double* dxdt) const {
    ++*count;
    const physics::DirectSystem::State xs = Eigen::Map<const physics::DirectSystem::State>(x);
    physics::DirectSystem::State d;
    sys->rhs(0.0, xs, d);
    std::copy(d.data(), d.data() + 6, dxdt);
  }
};

// One run of a C++ peer from t = 0 towards t_end.
struct PeerRun {
  std::array<double, 6> x{};  // the state reached: (Omega, gamma)
  double t = 0.0;             // the time reached
  long rhs = 0, steps = 0;
  std::string failure;  // "" = ok
};

}  // namespace epviz::study::peers
