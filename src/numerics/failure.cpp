#include "numerics/failure.hpp"

#include <cstdio>

namespace epviz::numerics {

std::string Failure::message() const {
  char when[64];
  std::snprintf(when, sizeof when, "%.10g", t);
  std::string m = method + " failed at t = " + when + ": " + reason;
  if (!suggestion.empty()) m += "; " + suggestion;
  return m;
}

IntegrationError::IntegrationError(Failure f)
    : std::runtime_error(f.message()), failure_(std::move(f)) {}

}  // namespace epviz::numerics
