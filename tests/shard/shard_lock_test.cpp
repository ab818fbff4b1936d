// A shard's lock: one holder at a time, named to whoever else tries; a
// heartbeat that keeps it fresh; and a lock left by a process that died
// (this host: its pid is gone; another: its heartbeat is stale) taken over.
#include "shard/shard_lock.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <stop_token>
#include <thread>

#include <nlohmann/json.hpp>

#include "io/temp_name.hpp"
#include "support/dead_pid.hpp"
#include "support/eventually.hpp"
#include "support/temp_dir.hpp"

namespace epviz::shard {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// A lock file as a holder on `machine` with `pid` leaves it, last renewed `age` ago.
void write_lock(const fs::path& path, const std::string& machine, long pid,
                std::chrono::seconds age = 0s) {
  std::ofstream(path) << nlohmann::json{{"host", "node7"},
                                        {"machine", machine},
                                        {"pid", pid},
                                        {"started", "2026-01-02T03:04:05Z"}}
                             .dump();
  fs::last_write_time(path, fs::file_time_type::clock::now() - age);
}

// The message of the ShardBusy that taking the lock at `path` throws ("" when it does not).
std::string refusal(const fs::path& path, std::chrono::milliseconds watch = heartbeat_watch) {
  try {
    ShardLock again(path, watch);
  } catch (const ShardBusy& e) {
    return e.what();
  }
  return "";
}

TEST(ShardLock, ASecondHolderIsRefusedNamingTheFirstUntilItEnds) {
  const test::TempDir dir;
  const auto path = dir / "rows.shard-0-of-2.lock";
  {
    const ShardLock first(path);
    const auto holder = nlohmann::json::parse(test::slurp(path));
    EXPECT_EQ(holder["pid"], long(::getpid()));
    EXPECT_EQ(holder["machine"], io::machine_token());
    const auto why = refusal(path);
    EXPECT_NE(why.find("rows.shard-0-of-2.lock: this shard is being run by host "),
              std::string::npos)
        << why;
    EXPECT_NE(why.find(", pid " + std::to_string(::getpid()) + ", since " +
                       holder["started"].get<std::string>()),
              std::string::npos)
        << why;
    EXPECT_EQ(probe_lock(path).state, LockState::running);
  }
  EXPECT_FALSE(fs::exists(path)) << "the lock outlived its holder";
  EXPECT_EQ(probe_lock(path).state, LockState::free);
  EXPECT_EQ(refusal(path), "");
}

TEST(ShardLock, TheHeartbeatRenewsTheLockFile) {
  const test::TempDir dir;
  const auto path = dir / "a.lock";
  const ShardLock lock(path);
  const auto old = fs::file_time_type::clock::now() - 10min;
  fs::last_write_time(path, old);
  EXPECT_TRUE(test::eventually([&] { return fs::last_write_time(path) > old + 9min; },
                               3 * heartbeat_interval));
}

TEST(ShardLock, ALockLeftByADeadProcessOfThisHostIsTakenOver) {
  const test::TempDir dir;
  const auto path = dir / "a.lock";
  const long dead = test::dead_pid();
  write_lock(path, io::machine_token(), dead);  // fresh: only the pid tells
  const auto seen = probe_lock(path);
  EXPECT_EQ(seen.state, LockState::dead);
  EXPECT_EQ(seen.why, "no such process on this host");
  const ShardLock lock(path);
  ASSERT_TRUE(lock.taken_over().has_value());
  EXPECT_EQ(lock.taken_over()->pid, dead);
  EXPECT_EQ(nlohmann::json::parse(test::slurp(path))["pid"], long(::getpid()));
}

TEST(ShardLock, ALiveProcessOfThisHostKeepsItsLockThoughItsFlockIsNotSeen) {
  // As where flock is not shared: the file names a live process of this host.
  const test::TempDir dir;
  const auto path = dir / "a.lock";
  write_lock(path, io::machine_token(), long(::getppid()), 1h);
  EXPECT_EQ(probe_lock(path).state, LockState::running);
  EXPECT_NE(refusal(path).find("pid " + std::to_string(::getppid())), std::string::npos);
}

TEST(ShardLock, AnotherHostsLockHoldsWhileItsHeartbeatGoesOn) {
  const test::TempDir dir;
  const auto path = dir / "a.lock";
  write_lock(path, "0123456789ab", 4242, heartbeat_stale - 10s);
  EXPECT_EQ(probe_lock(path).state, LockState::running);
  {
    // Its holder beats, as one on a node that does not share our flock would.
    // Its beat every 20 ms is the holder's pace, not a wait on the test: the
    // wait ends at once when the test stops it.
    std::mutex m;
    std::condition_variable_any paced;
    std::jthread beating([&](std::stop_token stop) {
      std::unique_lock lk(m);
      do fs::last_write_time(path, fs::file_time_type::clock::now());
      while (!paced.wait_for(lk, stop, 20ms, [] { return false; }) && !stop.stop_requested());
    });
    const auto why = refusal(path, 5s);
    EXPECT_NE(why.find("host node7, pid 4242, since 2026-01-02T03:04:05Z (its heartbeat goes on)"),
              std::string::npos)
        << why;
  }
  // Fresh but no longer beating: a holder that died a moment ago.
  const ShardLock lock(path, 300ms);
  ASSERT_TRUE(lock.taken_over().has_value());
  EXPECT_EQ(lock.taken_over()->host, "node7");
}

TEST(ShardLock, AnotherHostsLockWithAStaleHeartbeatIsDeadAtOnce) {
  const test::TempDir dir;
  const auto path = dir / "a.lock";
  write_lock(path, "0123456789ab", 4242, heartbeat_stale + 10s);
  const auto stale = probe_lock(path);
  EXPECT_EQ(stale.state, LockState::dead);
  EXPECT_EQ(stale.why.rfind("no heartbeat for ", 0), 0u) << stale.why;
  const auto start = std::chrono::steady_clock::now();
  const ShardLock lock(path);
  EXPECT_LT(std::chrono::steady_clock::now() - start, heartbeat_watch) << "watched a stale lock";
  ASSERT_TRUE(lock.taken_over().has_value());
  EXPECT_EQ(lock.taken_over()->pid, 4242);
}

// A heartbeat an hour ahead is no clock skew: such a lock would stay
// "running" for that hour. It is dead, and the reason says so.
TEST(ShardLock, AHeartbeatFarInTheFutureIsNoHeartbeat) {
  const test::TempDir dir;
  const auto path = dir / "a.lock";
  write_lock(path, "0123456789ab", 4242, -1h);
  const auto seen = probe_lock(path);
  EXPECT_EQ(seen.state, LockState::dead);
  EXPECT_NE(seen.why.find("s in the future"), std::string::npos) << seen.why;
  const ShardLock lock(path, 300ms);
  ASSERT_TRUE(lock.taken_over().has_value());
  // Clocks a few seconds apart are not refused.
  const auto near = dir / "b.lock";
  write_lock(near, "0123456789ab", 4242, -clock_skew_allowed / 3);
  EXPECT_EQ(probe_lock(near).state, LockState::running);
}

// Opening a FIFO for reading waits for a writer: the merge's look at a lock
// must not. Should it wait, a writer opened here after 20 s lets it go on,
// and the test fails.
TEST(ShardLock, AFifoAtTheLockPathIsNotWaitedOn) {
  const test::TempDir dir;
  const auto path = dir / "a.lock";
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  std::atomic<bool> probed{false}, freed{false};
  std::jthread rescue([&](std::stop_token stop) {
    std::mutex m;
    std::condition_variable_any cv;
    std::unique_lock lk(m);
    if (cv.wait_for(lk, stop, 20s, [&] { return probed.load(); })) return;
    freed = true;
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
  });
  const auto seen = probe_lock(path);
  probed = true;
  rescue.request_stop();
  rescue.join();
  EXPECT_FALSE(freed.load()) << "probe_lock waited on the FIFO";
  EXPECT_EQ(seen.state, LockState::dead);
  EXPECT_NE(seen.why.find("a.lock: is a FIFO, not a shard lock of epviz"), std::string::npos)
      << seen.why;
}

// What is at a lock path and is not a lock of epviz is refused, not written
// through (a hard link's other name keeps its text) nor removed (the FIFO).
TEST(ShardLock, AFileThatIsNotALockOfEpvizIsRefusedAndKept) {
  const test::TempDir dir;
  const auto victim = dir / "victim.txt";
  std::ofstream(victim) << "precious";
  struct Case {
    std::string name, why;
    std::function<void(const fs::path&)> make;
  };
  const std::vector<Case> cases{
      {"hard", "has other hard links", [&](const fs::path& p) { fs::create_hard_link(victim, p); }},
      {"soft", "is a symbolic link", [&](const fs::path& p) { fs::create_symlink(victim, p); }},
      {"fifo", "is a FIFO", [](const fs::path& p) { ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0); }},
      {"dir", "is a directory", [](const fs::path& p) { fs::create_directory(p); }},
      {"text", "does not name a holder",
       [](const fs::path& p) { std::ofstream(p) << "my notes"; }}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const auto path = dir / (c.name + ".lock");
    c.make(path);
    std::string why;
    try {
      ShardLock lock(path, 100ms);
      ADD_FAILURE() << "taken";
    } catch (const ShardBusy& e) {
      ADD_FAILURE() << "taken for busy: " << e.what();
    } catch (const ShardError& e) {
      why = e.what();
    }
    EXPECT_NE(why.find(c.name + ".lock: " + c.why + ", not a shard lock of epviz"),
              std::string::npos)
        << why;
    EXPECT_TRUE(fs::exists(fs::symlink_status(path))) << "removed";
    EXPECT_EQ(test::slurp(victim), "precious");
  }
  EXPECT_TRUE(fs::is_fifo(dir / "fifo.lock"));
}

}  // namespace
}  // namespace epviz::shard
