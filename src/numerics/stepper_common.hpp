#pragma once
// What every stepper shares: the start-of-step hook (regularize), the
// end-of-step checks (non-finite state, the system's own check()) and the
// throwing of IntegrationError. The throwing helpers live out of line
// (stepper_common.cpp) so that the hot paths only carry a predictable branch.
#include <string>
#include <type_traits>
#include <utility>

#include "numerics/failure.hpp"
#include "numerics/system.hpp"

namespace epviz::numerics {

namespace detail {

// Throws IntegrationError(Failure{t, method, kind, detail}).
[[noreturn]] void throw_failure(double t, const char* method, FailureKind kind, std::string detail);

// The failure for a non-finite state (NaN or Inf) found at time t.
[[noreturn]] void throw_non_finite(double t, const char* method);

// The failure for an issue reported by the system's check().
[[noreturn]] void throw_issue(double t, const char* method, const Issue& issue);

// The system's check() (when it has one) must not object to x at time t.
template <class Sys>
inline void check_issue(const Sys& sys, const typename Sys::State& x, double t,
                        const char* method) {
  if constexpr (requires { sys.check(x); }) {
    if (auto issue = sys.check(x)) [[unlikely]]
      throw_issue(t, method, *issue);
  }
}

// End of an accepted step: the state must be finite and the system's check()
// must not object.
template <class Sys>
inline void check_accepted(const Sys& sys, const typename Sys::State& x, double t,
                           const char* method) {
  if (!x.allFinite()) [[unlikely]]
    throw_non_finite(t, method);
  check_issue(sys, x, t, method);
}

}  // namespace detail

// The system and the work counters a fixed-step stepper keeps, and the end of
// its step: the new state checked, accepted and counted. Derived steppers
// name the members with `using` so that the hot loops read them directly.
template <class Sys>
class StepperCore {
 public:
  explicit StepperCore(Sys sys) : sys_(std::move(sys)) {}

  Sys& system() { return sys_; }
  const Sys& system() const { return sys_; }
  const Stats& stats() const { return stats_; }
  void reset_stats() { stats_ = Stats{}; }

 protected:
  // x becomes x_new (the state at time t) unless the checks throw.
  void accept(typename Sys::State& x, const typename Sys::State& x_new, double t,
              const char* method) {
    detail::check_accepted(sys_, x_new, t, method);
    x = x_new;
    ++stats_.steps;
  }

  Sys sys_;
  Stats stats_;
};

// A system that can be split into exactly solvable sub-flows (Strang splitting).
template <class Sys>
concept SplittableSystem = requires(const Sys& s, int i, double h, typename Sys::State& x) {
  { Sys::dim } -> std::convertible_to<int>;
  { Sys::n_flows } -> std::convertible_to<int>;
  s.flow(i, h, x);
};

}  // namespace epviz::numerics
