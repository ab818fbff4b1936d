#include "io/subprocess.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "io/errno_text.hpp"

extern char** environ;

namespace epviz::io {
namespace {

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

// Blocks SIGPIPE in this thread for the guard's lifetime; a SIGPIPE raised
// meanwhile by a write to a closed pipe is consumed before the mask is restored
// (unless one was already pending before, which is then not ours to take).
class SigpipeGuard {
 public:
  SigpipeGuard() {
    sigset_t block;
    sigemptyset(&block);
    sigaddset(&block, SIGPIPE);
    ::pthread_sigmask(SIG_BLOCK, &block, &old_);
    sigset_t pending;
    sigemptyset(&pending);
    ::sigpending(&pending);
    was_pending_ = sigismember(&pending, SIGPIPE) == 1;
  }
  ~SigpipeGuard() {
    if (!was_pending_) {
      sigset_t pending;
      sigemptyset(&pending);
      ::sigpending(&pending);
      if (sigismember(&pending, SIGPIPE) == 1) {
        sigset_t pipe_only;
        sigemptyset(&pipe_only);
        sigaddset(&pipe_only, SIGPIPE);
        const timespec zero{0, 0};
        const int saved = errno;
        while (::sigtimedwait(&pipe_only, nullptr, &zero) < 0 && errno == EINTR) {
        }
        errno = saved;
      }
    }
    ::pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeGuard(const SigpipeGuard&) = delete;
  SigpipeGuard& operator=(const SigpipeGuard&) = delete;

 private:
  sigset_t old_{};
  bool was_pending_ = false;
};

// The pipes of one spawn, closed on every path that does not hand them over.
struct Pipes {
  int fds[3][2] = {{-1, -1}, {-1, -1}, {-1, -1}};
  ~Pipes() {
    for (auto& p : fds) {
      close_fd(p[0]);
      close_fd(p[1]);
    }
  }
};

}  // namespace

bool ExitStatus::exited() const { return raw != -1 && WIFEXITED(raw); }
int ExitStatus::code() const { return exited() ? WEXITSTATUS(raw) : -1; }
bool ExitStatus::signalled() const { return raw != -1 && WIFSIGNALED(raw); }
int ExitStatus::signal() const { return signalled() ? WTERMSIG(raw) : 0; }

std::string ExitStatus::describe() const {
  if (raw == -1) return "could not be waited for";
  if (exited()) return "exited with status " + std::to_string(code());
  if (signalled()) return std::string("was killed by signal ") + ::strsignal(signal());
  return "ended abnormally";
}

Subprocess::Subprocess(const std::vector<std::string>& argv, const Options& options) {
  if (argv.empty() || argv[0].empty()) throw SubprocessError("no program to start", EINVAL);
  const Stream streams[3] = {options.in, options.out, options.err};
  Pipes pipes;
  for (int i = 0; i < 3; ++i)
    if (streams[i] == Stream::pipe && ::pipe2(pipes.fds[i], O_CLOEXEC) != 0) {
      const int error = errno;
      throw SubprocessError("cannot start " + argv[0] + ": pipe: " + errno_text(error), error);
    }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  for (int i = 0; i < 3; ++i) {
    switch (streams[i]) {
      case Stream::pipe:
        // The child's end: the read end of stdin's pipe, the write end of the others'.
        posix_spawn_file_actions_adddup2(&actions, pipes.fds[i][i == 0 ? 0 : 1], i);
        break;
      case Stream::null:
        posix_spawn_file_actions_addopen(&actions, i, "/dev/null", i == 0 ? O_RDONLY : O_WRONLY, 0);
        break;
      case Stream::fd: posix_spawn_file_actions_adddup2(&actions, options.err_fd, i); break;
      case Stream::inherit: break;
    }
  }
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  sigset_t empty;
  sigemptyset(&empty);
  posix_spawnattr_setsigmask(&attr, &empty);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = ::posix_spawnp(&pid, args[0], &actions, &attr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (spawned != 0)
    throw SubprocessError("cannot start " + argv[0] + ": " + errno_text(spawned), spawned);
  pid_ = pid;
  std::swap(in_, pipes.fds[0][1]);
  std::swap(out_, pipes.fds[1][0]);
  std::swap(err_, pipes.fds[2][0]);
}

Subprocess::~Subprocess() {
  close_fd(in_);
  close_fd(out_);
  close_fd(err_);
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    wait();
  }
}

int Subprocess::write_stdin(const void* data, std::size_t size) {
  if (in_ < 0) return EBADF;
  SigpipeGuard guard;
  const auto* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(in_, bytes, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  return 0;
}

void Subprocess::close_stdin() { close_fd(in_); }

int Subprocess::communicate(const std::string& input, std::string& out, std::string& err) {
  int write_error = 0;
  std::size_t written = 0;
  if (in_ >= 0 && input.empty()) close_stdin();
  if (in_ >= 0) ::fcntl(in_, F_SETFL, ::fcntl(in_, F_GETFL) | O_NONBLOCK);
  SigpipeGuard guard;
  char buffer[65536];
  while (in_ >= 0 || out_ >= 0 || err_ >= 0) {
    pollfd fds[3] = {{in_, POLLOUT, 0}, {out_, POLLIN, 0}, {err_, POLLIN, 0}};
    if (::poll(fds, 3, -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    if (in_ >= 0 && fds[0].revents) {
      const ssize_t n = ::write(in_, input.data() + written, input.size() - written);
      if (n >= 0)
        written += std::size_t(n);
      else if (errno != EINTR && errno != EAGAIN)
        write_error = errno;
      if (written == input.size() || write_error) close_stdin();
    }
    int* readers[2] = {&out_, &err_};
    std::string* sinks[2] = {&out, &err};
    for (int i = 0; i < 2; ++i) {
      if (*readers[i] < 0 || !fds[i + 1].revents) continue;
      const ssize_t n = ::read(*readers[i], buffer, sizeof buffer);
      if (n > 0)
        sinks[i]->append(buffer, std::size_t(n));
      else if (n == 0 || (errno != EINTR && errno != EAGAIN))
        close_fd(*readers[i]);
    }
  }
  return write_error;
}

ExitStatus Subprocess::wait() {
  if (pid_ <= 0) return status_;
  int status = 0;
  pid_t result;
  do {
    result = ::waitpid(pid_, &status, 0);
  } while (result < 0 && errno == EINTR);
  pid_ = -1;
  status_.raw = result < 0 ? -1 : status;
  return status_;
}

void Subprocess::kill(int signal) {
  if (pid_ > 0) ::kill(pid_, signal);
}

ProcessOutput run_process(const std::vector<std::string>& argv, const std::string& input) {
  Subprocess child(argv);
  ProcessOutput po;
  child.communicate(input, po.out, po.err);
  po.status = child.wait();
  return po;
}

}  // namespace epviz::io
