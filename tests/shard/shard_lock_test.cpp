// A shard's lock: one holder at a time, named to whoever else tries; a
// heartbeat that keeps it fresh; and a lock left by a process that died
// (this host: its pid is gone; another: its heartbeat is stale) taken over.
#include "shard/shard_lock.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
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

}  // namespace
}  // namespace epviz::shard
