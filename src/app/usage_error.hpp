#pragma once
// Bad input from the user: the CLI prints the one-line message and exits 2.
#include <stdexcept>

namespace epviz::app {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace epviz::app
