#include "numerics/stepper_common.hpp"

#include <utility>

namespace epviz::numerics::detail {

void throw_failure(double t, const char* method, std::string reason, std::string suggestion) {
  throw IntegrationError(Failure{t, method, std::move(reason), std::move(suggestion)});
}

void throw_non_finite(double t, const char* method, const char* hint) {
  throw_failure(t, method, "non-finite state (NaN or Inf)", hint);
}

void throw_issue(double t, const char* method, const Issue& issue) {
  throw_failure(t, method, issue.reason, issue.suggestion);
}

}  // namespace epviz::numerics::detail
