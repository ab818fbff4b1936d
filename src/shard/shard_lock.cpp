#include "shard/shard_lock.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <condition_variable>
#include <cstring>
#include <ctime>
#include <mutex>
#include <thread>

#include <nlohmann/json.hpp>

#include "io/json_text.hpp"
#include "io/printable.hpp"
#include "io/temp_name.hpp"

namespace epviz::shard {

namespace fs = std::filesystem;
using std::chrono::seconds;

namespace {

std::string host_name() {
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) != 0) return "?";
  return host;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  ::gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

std::string holder_text(const LockHolder& h) {
  return io::json_text(nlohmann::json{
             {"host", h.host}, {"machine", h.machine}, {"pid", h.pid}, {"started", h.started}}) +
         "\n";
}

// The holder the open file names; nullopt when it is empty (its writer is
// between creating and filling it) or not a holder.
std::optional<LockHolder> read_holder(int fd) {
  std::string text(4096, '\0');
  const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
  if (n <= 0) return std::nullopt;
  text.resize(std::size_t(n));
  const auto j = io::parse_json_or_discarded(text);
  if (!j.is_object()) return std::nullopt;
  LockHolder h;
  const auto str = [&](const char* key) {
    const auto it = j.find(key);
    return it != j.end() && it->is_string() ? io::printable(it->get<std::string>(), 100)
                                            : std::string("?");
  };
  h.host = str("host");
  h.machine = str("machine");
  h.started = str("started");
  const auto pid = j.find("pid");
  if (pid == j.end() || !pid->is_number_integer()) return std::nullopt;
  h.pid = pid->get<long>();
  return h;
}

// Time since the open file was last modified: negative when that time is
// ahead of our clock (another node's clock, or a forged time).
seconds heartbeat_age(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) return seconds{0};
  const auto mtime = std::chrono::system_clock::time_point(
      std::chrono::duration_cast<std::chrono::system_clock::duration>(
          seconds(st.st_mtim.tv_sec) + std::chrono::nanoseconds(st.st_mtim.tv_nsec)));
  return std::chrono::duration_cast<seconds>(std::chrono::system_clock::now() - mtime);
}

bool process_exists(long pid) {
  // ESRCH only when there is no such process; EPERM: one of another user.
  return pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno != ESRCH);
}

// Whether a lock whose flock is free (or not shared with its holder's node)
// is still held: on this machine its pid says so; elsewhere its heartbeat.
LockStatus judge(const std::optional<LockHolder>& holder, seconds age) {
  LockStatus s{LockState::running, holder, age, ""};
  if (holder && holder->machine == io::machine_token()) {
    const bool alive = process_exists(holder->pid);
    s.state = alive ? LockState::running : LockState::dead;
    s.why = alive ? "its process is alive" : "no such process on this host";
    return s;
  }
  // A time ahead of ours by more than clocks differ is no heartbeat: it would
  // keep the lock "running" until that time comes.
  if (age < -clock_skew_allowed) {
    s.state = LockState::dead;
    s.why = "its heartbeat is " + std::to_string(-age.count()) +
            " s in the future, which no live holder writes (clocks differ by at most " +
            std::to_string(clock_skew_allowed.count()) + " s)";
    return s;
  }
  if (age < seconds{0}) s.heartbeat_age = age = seconds{0};
  const bool fresh = age < heartbeat_stale;
  s.state = fresh ? LockState::running : LockState::dead;
  s.why = (fresh ? "heartbeat " : "no heartbeat for ") + std::to_string(age.count()) +
          (fresh ? " s ago" : " s");
  return s;
}

// The modification time of the file at `path` now; nullopt when it is gone.
// Opened afresh each time: NFS then asks the server, not its cache.
std::optional<std::timespec> modified(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  const bool ok = ::fstat(fd, &st) == 0;
  ::close(fd);
  if (!ok) return std::nullopt;
  return st.st_mtim;
}

// A fresh lock of another machine whose flock was free: alive where flock is
// not shared between nodes, dead where it is. A beat within `watch` tells.
LockStatus watch_heartbeat(const fs::path& path, LockStatus s, std::chrono::milliseconds watch) {
  const auto first = modified(path);
  const auto deadline = std::chrono::steady_clock::now() + watch;
  while (std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const auto now = modified(path);
    if (first && now && (now->tv_sec != first->tv_sec || now->tv_nsec != first->tv_nsec)) {
      s.why = "its heartbeat goes on";
      return s;
    }
  }
  s.state = LockState::dead;
  s.why = "no heartbeat for " + std::to_string((watch.count() + 999) / 1000) + " s";
  return s;
}

// What keeps the open file from being a lock file of epviz ("" when it is
// one): anything but a regular file with one name, or a file that holds
// something other than a holder (an empty one is being made).
std::string lock_file_problem(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) return std::strerror(errno);
  if (S_ISFIFO(st.st_mode)) return "is a FIFO";
  if (S_ISDIR(st.st_mode)) return "is a directory";
  if (!S_ISREG(st.st_mode)) return "is not a regular file";
  if (st.st_nlink != 1) return "has other hard links";
  if (st.st_size > 0 && !read_holder(fd)) return "does not name a holder";
  return "";
}

std::string not_a_lock(const fs::path& path, const std::string& why) {
  return io::printable(path.string(), 300) + ": " + why +
         ", not a shard lock of epviz; move it away and run again";
}

std::string busy_message(const fs::path& path, const LockStatus& s) {
  return io::printable(path.string(), 300) + ": this shard is being run by " +
         (s.holder ? describe(*s.holder) : std::string("another process")) + " (" + s.why +
         "); wait for it to end, or stop it and run again";
}

}  // namespace

std::string describe(const LockHolder& h) {
  std::string s = "host " + h.host + ", pid ";
  s += std::to_string(h.pid);
  s += ", since " + h.started;
  return s;
}

LockStatus probe_lock(const fs::path& path) {
  // Opening (not only stat) makes NFS fetch the file's attributes afresh;
  // without blocking, which opening a FIFO for reading would.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) {
    if (errno == ENOENT) return {};
    return {LockState::dead, std::nullopt, seconds{0}, not_a_lock(path, "cannot be opened")};
  }
  if (const auto why = lock_file_problem(fd); !why.empty()) {
    ::close(fd);
    return {LockState::dead, std::nullopt, seconds{0}, not_a_lock(path, why)};
  }
  LockStatus s = judge(read_holder(fd), heartbeat_age(fd));
  if (::flock(fd, LOCK_SH | LOCK_NB) != 0) {
    if (errno == EWOULDBLOCK) {
      s.state = LockState::running;
      if (s.why.empty() || s.why.starts_with("no ")) s.why = "its lock is held";
    }
  } else {
    ::flock(fd, LOCK_UN);
  }
  ::close(fd);
  return s;
}

struct ShardLock::Held {
  fs::path path;
  int fd = -1;
  std::optional<LockHolder> taken_over;
  std::mutex mutex;
  std::condition_variable wake;
  bool stopping = false;
  std::thread heartbeat;

  ~Held() {
    if (heartbeat.joinable()) {
      {
        std::lock_guard lock(mutex);
        stopping = true;
      }
      wake.notify_all();
      heartbeat.join();
    }
    if (fd >= 0) {
      ::unlink(path.c_str());  // while still locked: a waiter then finds the file gone
      ::close(fd);
    }
  }

  void beat() {
    std::unique_lock lock(mutex);
    while (!wake.wait_for(lock, heartbeat_interval, [&] { return stopping; }))
      ::futimens(fd, nullptr);  // a failed renewal only makes the lock look older
  }
};

ShardLock::ShardLock(const fs::path& path, std::chrono::milliseconds watch)
    : held_(std::make_unique<Held>()) {
  held_->path = path;
  const std::string name = io::printable(path.string(), 300);
  // A holder that ends removes the file while still holding its flock; a
  // copy that opened the file just before takes the flock of a file that no
  // longer has this name, and so tries again.
  // The file is made exclusively and never followed: whatever else is at the
  // path (a link to another file, a FIFO) is refused, not written or removed.
  for (int attempt = 0; held_->fd < 0; ++attempt) {
    if (attempt >= 100) throw ShardError(name + ": the lock file keeps being replaced");
    int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0 && errno == EEXIST)
      fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0 && errno == ENOENT) continue;  // its holder ended meanwhile
    if (fd < 0 && errno == ELOOP) throw ShardError(not_a_lock(path, "is a symbolic link"));
    if (fd < 0 && errno == EISDIR) throw ShardError(not_a_lock(path, "is a directory"));
    if (fd < 0)
      throw ShardError(name + ": cannot open the shard's lock file (" + std::strerror(errno) + ")");
    if (const auto why = lock_file_problem(fd); !why.empty()) {
      ::close(fd);
      throw ShardError(not_a_lock(path, why));
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      LockStatus s{LockState::running, read_holder(fd), heartbeat_age(fd), "its lock is held"};
      ::close(fd);
      if (error == EWOULDBLOCK) throw ShardBusy(busy_message(path, s));
      throw ShardError(name + ": cannot lock (" + std::strerror(error) + ")");
    }
    struct stat opened {
    }, named{};
    if (::fstat(fd, &opened) != 0 || ::stat(path.c_str(), &named) != 0 ||
        opened.st_ino != named.st_ino || opened.st_dev != named.st_dev) {
      ::close(fd);
      continue;
    }
    // Ours by flock; but where flock is not shared between nodes, a holder on
    // another node shows only by its heartbeat.
    if (const auto holder = read_holder(fd)) {
      auto s = judge(holder, heartbeat_age(fd));
      const bool here = holder->machine == io::machine_token();
      if (s.state == LockState::running && !here) s = watch_heartbeat(path, s, watch);
      if (s.state == LockState::running && !(here && holder->pid == long(::getpid()))) {
        ::close(fd);
        throw ShardBusy(busy_message(path, s));
      }
      held_->taken_over = holder;
    }
    held_->fd = fd;
  }
  const std::string text =
      holder_text({host_name(), io::machine_token(), long(::getpid()), utc_now()});
  // Synced: NFS would otherwise keep the holder's name on this client for a
  // while, and another node would read an empty lock.
  if (::ftruncate(held_->fd, 0) != 0 ||
      ::pwrite(held_->fd, text.data(), text.size(), 0) != ssize_t(text.size()) ||
      ::fsync(held_->fd) != 0)
    throw ShardError(name + ": cannot write the shard's lock file (" + std::strerror(errno) + ")");
  held_->heartbeat = std::thread([h = held_.get()] { h->beat(); });
}

ShardLock::~ShardLock() = default;
ShardLock::ShardLock(ShardLock&&) noexcept = default;
ShardLock& ShardLock::operator=(ShardLock&&) noexcept = default;

const std::optional<LockHolder>& ShardLock::taken_over() const { return held_->taken_over; }

}  // namespace epviz::shard
