#pragma once
// A child process started from an argument list (posix_spawnp: no shell, so
// no quoting and any path works; a program name without '/' is searched on
// PATH), with its standard streams piped, sent to /dev/null, inherited or
// given a file descriptor of ours.
//
// Writing to a child that has exited raises no SIGPIPE in this process:
// SIGPIPE is blocked in the writing thread around each write and a resulting
// pending SIGPIPE is consumed, so the write reports EPIPE instead. The child
// itself starts with default signal dispositions and an empty signal mask
// whatever this process uses.
//
//   auto out = io::run_process({"/usr/bin/python3", "driver.py"}, input_json);
//   if (!out.status.success()) ... out.status.describe() ... out.err ...
#include <sys/types.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace epviz::io {

// Thrown when a process cannot be started (errno_value says why: ENOENT when
// the program is not found) or a pipe cannot be made.
class SubprocessError : public std::runtime_error {
 public:
  SubprocessError(const std::string& what, int error_number)
      : std::runtime_error(what), errno_value(error_number) {}
  int errno_value;
};

// How a child ended: the raw wait status.
struct ExitStatus {
  int raw = -1;  // -1: not waited for (or the wait failed)
  bool exited() const;
  int code() const;  // the exit code when exited(), else -1
  bool signalled() const;
  int signal() const;  // the signal when signalled(), else 0
  bool success() const { return exited() && code() == 0; }
  // "exited with status 3", "was killed by signal Killed", "could not be waited for".
  std::string describe() const;
};

class Subprocess {
 public:
  enum class Stream { pipe, null, inherit, fd };
  struct Options {
    Stream in = Stream::pipe;
    Stream out = Stream::pipe;
    Stream err = Stream::pipe;
    int err_fd = -1;  // with err = Stream::fd: the child's stderr (ours stays open)
  };

  // Starts argv[0] with arguments argv. Throws SubprocessError.
  Subprocess(const std::vector<std::string>& argv, const Options& options);
  explicit Subprocess(const std::vector<std::string>& argv) : Subprocess(argv, Options{}) {}
  // A child still running is killed (SIGKILL) and reaped.
  ~Subprocess();
  Subprocess(const Subprocess&) = delete;
  Subprocess& operator=(const Subprocess&) = delete;

  pid_t pid() const { return pid_; }
  bool running() const { return pid_ > 0; }

  // Writes all `size` bytes to the child's stdin, blocking while its pipe is
  // full. Returns 0, or the errno of the failed write: EPIPE when the child
  // no longer reads (it exited or closed its stdin).
  int write_stdin(const void* data, std::size_t size);
  // Closes our end of the child's stdin (the child sees end of file).
  void close_stdin();

  // Writes `input` to stdin (then closes it) while reading stdout and stderr
  // to their end, so that no pipe can fill up and block either side; the
  // streams that are not pipes are skipped. Returns the errno of a failed
  // write to stdin (EPIPE: the child stopped reading), else 0.
  int communicate(const std::string& input, std::string& out, std::string& err);

  // Waits for the child (once; later calls return the same status).
  ExitStatus wait();
  // Sends a signal to the running child.
  void kill(int signal);

 private:
  pid_t pid_ = -1;
  int in_ = -1, out_ = -1, err_ = -1;  // our ends of the pipes
  ExitStatus status_;
};

// Runs argv with `input` on stdin, collecting stdout and stderr, and waits.
struct ProcessOutput {
  ExitStatus status;
  std::string out, err;
};
ProcessOutput run_process(const std::vector<std::string>& argv, const std::string& input = {});

}  // namespace epviz::io
