#pragma once
// Who runs a shard now. A shard's process holds an exclusive flock on a lock
// file beside its output for as long as it runs; the file says who holds it
// (host, machine, pid, start time) and its modification time is renewed every
// heartbeat_interval by a thread of its own. A second copy of the shard finds
// the flock taken and refuses, naming the holder. Where flock is not shared
// between the nodes that see the file (docs/cluster.md), the heartbeat stands
// in for it. A lock left by a process that died (kill -9, a node lost) is
// taken over: on the same machine once its pid is gone; from another
// machine once its heartbeat is stale, or, when it is not, once it has not
// beaten for heartbeat_watch. `epviz merge`, which cannot wait, takes a lock
// renewed within heartbeat_stale for a live one.
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "shard/shard_spec.hpp"

namespace epviz::shard {

inline constexpr std::chrono::seconds heartbeat_interval{5};
// Long enough for a heartbeat to reach another node through NFS's attribute
// cache and for clocks a few seconds apart; short enough that a merge soon
// calls a lost node's shard dead.
inline constexpr std::chrono::seconds heartbeat_stale{60};
// How far another node's clock may run ahead of ours: a heartbeat further
// in the future is not one (a forged time would keep a lock "running").
inline constexpr std::chrono::seconds clock_skew_allowed{30};
// How long a new holder watches a fresh lock of another machine for a beat
// before it takes the lock for dead: two beats and some slack.
inline constexpr std::chrono::milliseconds heartbeat_watch =
    2 * heartbeat_interval + std::chrono::seconds{2};

struct LockHolder {
  std::string host;     // the host name, for people
  std::string machine;  // io::machine_token(): with the pid, one process
  long pid = 0;
  std::string started;  // UTC, "2026-11-26T13:20:05Z"
};

// "host node7, pid 4242, since 2026-11-26T13:20:05Z".
std::string describe(const LockHolder& h);

enum class LockState { free, running, dead };

struct LockStatus {
  LockState state = LockState::free;
  std::optional<LockHolder> holder;      // as the file says; nullopt when unreadable
  std::chrono::seconds heartbeat_age{};  // since the file was last renewed
  std::string why;                       // for a running or dead lock: how it is known
};

// What the lock file at `path` says now, without taking it (none there: free).
LockStatus probe_lock(const std::filesystem::path& path);

// A second copy of a shard: io::BadInput (exit 2), naming the holder.
class ShardBusy : public ShardError {
 public:
  using ShardError::ShardError;
};

class ShardLock {
 public:
  // Takes the lock at `path`, taking over a dead holder's (`watch`: how long
  // to watch another machine's fresh lock for a beat). Throws ShardBusy
  // naming the live holder, or ShardError when the file cannot be made.
  explicit ShardLock(const std::filesystem::path& path,
                     std::chrono::milliseconds watch = heartbeat_watch);
  // Stops the heartbeat and removes the lock file.
  ~ShardLock();
  ShardLock(ShardLock&&) noexcept;
  ShardLock& operator=(ShardLock&&) noexcept;

  // The dead holder whose lock this one took over, if any.
  const std::optional<LockHolder>& taken_over() const;

 private:
  struct Held;
  std::unique_ptr<Held> held_;
};

}  // namespace epviz::shard
