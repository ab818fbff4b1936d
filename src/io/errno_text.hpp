#pragma once
// The system's message for an errno value ("No such file or directory"), for
// the errors of the files that make system calls.
#include <string>
#include <system_error>

namespace epviz::io {

inline std::string errno_text(int error) { return std::system_category().message(error); }

}  // namespace epviz::io
