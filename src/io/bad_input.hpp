#pragma once
// Input a user gave that cannot be used: an option, a job or sweep file, a
// manifest, a variable of the environment. The message names where it came
// from (the option, or the file and key), what was given and what is allowed,
// on one line. Every reader's error derives from it, so that the command line
// maps all of them to exit code 2 in one place (app/main.cpp).
#include <stdexcept>

namespace epviz::io {

class BadInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace epviz::io
