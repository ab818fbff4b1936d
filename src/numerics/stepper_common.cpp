#include "numerics/stepper_common.hpp"

#include <utility>

namespace epviz::numerics::detail {

void throw_failure(double t, const char* method, FailureKind kind, std::string detail) {
  throw IntegrationError(Failure{t, method, kind, std::move(detail)});
}

void throw_non_finite(double t, const char* method) {
  throw_failure(t, method, FailureKind::non_finite, "state not finite (NaN or Inf)");
}

void throw_issue(double t, const char* method, const Issue& issue) {
  throw_failure(t, method, issue.kind, issue.detail);
}

}  // namespace epviz::numerics::detail
