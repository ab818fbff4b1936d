#pragma once
// The message of the exception a piece of code is expected to throw.
#include <gtest/gtest.h>

#include <exception>
#include <string>

namespace epviz::test {

// What `f` throws as an E, or "" and a test failure when it throws none.
template <class E = std::exception, class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception thrown";
  return "";
}

}  // namespace epviz::test
