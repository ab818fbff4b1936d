#pragma once
// A process id that no process has: that of a child that has exited and been
// reaped (until the kernel hands the id out again, far later).
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace epviz::test {

inline pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

}  // namespace epviz::test
