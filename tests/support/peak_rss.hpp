#pragma once
// The peak resident memory of one run of the built epviz binary, for the
// tests that check that memory does not grow with the size of the input.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

namespace epviz::test {

// Runs epviz with `args` (stdout to /dev/null) in `cwd`; its peak RSS in kB,
// or -1 when it did not exit with 0.
inline long peak_rss_kb(const std::vector<std::string>& args, const std::string& cwd = ".") {
  std::vector<char*> argv{const_cast<char*>(EPVIZ_BINARY)};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    if (!std::freopen("/dev/null", "w", stdout) || ::chdir(cwd.c_str()) != 0) ::_exit(126);
    ::execv(EPVIZ_BINARY, argv.data());
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  if (::wait4(child, &status, 0, &usage) != child || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return -1;
  return usage.ru_maxrss;
}

}  // namespace epviz::test
