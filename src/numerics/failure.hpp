#pragma once
// How an integrator says that it cannot go on. Every stepper throws
// IntegrationError instead of returning a state it does not trust.
#include <stdexcept>
#include <string>

namespace epviz::numerics {

struct Failure {
  double t = 0.0;          // time at which the failure was detected
  std::string method;      // e.g. "dop853"
  std::string reason;      // what went wrong, e.g. "step size underflow (h = 3e-17)"
  std::string suggestion;  // what the user can do about it

  // One line: "dop853 failed at t = 1.2345: <reason>; <suggestion>"
  std::string message() const;
};

class IntegrationError : public std::runtime_error {
 public:
  explicit IntegrationError(Failure f);
  const Failure& failure() const noexcept { return failure_; }

 private:
  Failure failure_;
};

}  // namespace epviz::numerics
