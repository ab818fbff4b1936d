// Temporaries are removed on SIGINT/SIGTERM, and stale ones of dead processes
// on the next run.
#include "io/temp_registry.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>

#include "io/atomic_file.hpp"
#include "io/temp_name.hpp"
#include "support/dead_pid.hpp"
#include "support/temp_dir.hpp"

namespace epviz::io {
namespace {

namespace fs = std::filesystem;

using TempRegistryTest = test::TempDirTest;

using test::dead_pid;

std::string temporary(const std::string& name, pid_t pid,
                      const std::string& machine = machine_token()) {
  return name + temporary_suffix(pid, machine);
}

TEST(TemporaryName, ParsesOnlyTheTemporaryShape) {
  const auto t = parse_temporary_name(temporary("a.mp4", 1234));
  ASSERT_TRUE(t);
  EXPECT_EQ(t->pid, 1234);
  EXPECT_EQ(t->machine, machine_token());
  EXPECT_EQ(machine_token().size(), 12u);
  for (const char* name :
       {"a.mp4", "a.mp4.tmp-1234", "notes.txt.tmp-999999", "a.epviz-tmp-",
        "a.epviz-tmp-0123456789ab-", "a.epviz-tmp-0123456789ab-12x", "a.epviz-tmp-0123456789AB-12",
        "a.epviz-tmp-0123456789a-12", ".epviz-tmp-0123456789ab-12", "a.epviz-tmp-0123456789ab-0"})
    EXPECT_FALSE(parse_temporary_name(name)) << name;
}

TEST_F(TempRegistryTest, StaleTemporariesOfDeadProcessesAreRemoved) {
  const pid_t dead = dead_pid();
  const pid_t live = ::getppid();  // the test runner's parent is alive
  const auto stale = dir_ / temporary("x.mp4", dead);
  const auto busy = dir_ / temporary("y.mp4", live);
  const auto ours = dir_ / temporary("z.csv", ::getpid());
  const auto unrelated = dir_ / "notes.txt";
  // Not epviz's, though it looks like a temporary of a dead process.
  const auto users = dir_ / ("notes.txt.tmp-" + std::to_string(dead));
  for (const auto& p : {stale, busy, ours, unrelated, users}) std::ofstream(p) << "x";
  fs::create_directories(dir_ / temporary("d", dead));  // not a file: kept

  const auto removed = remove_stale_temporaries(dir_);
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_EQ(removed[0], stale);
  EXPECT_FALSE(fs::exists(stale));
  for (const auto& p : {busy, ours, unrelated, users}) EXPECT_TRUE(fs::exists(p)) << p;
  EXPECT_TRUE(fs::exists(dir_ / temporary("d", dead)));
}

TEST_F(TempRegistryTest, AnotherMachinesTemporaryIsRemovedOnlyWhenLongUnmodified) {
  // Another host, boot or PID namespace: its pids say nothing here, so a
  // temporary whose pid is dead here may be alive there.
  const std::string elsewhere = machine_token() == "0123456789ab" ? "ba9876543210" : "0123456789ab";
  const auto live_there = dir_ / temporary("a.mp4", dead_pid(), elsewhere);
  const auto dead_there = dir_ / temporary("b.mp4", dead_pid(), elsewhere);
  for (const auto& p : {live_there, dead_there}) std::ofstream(p) << "x";
  fs::last_write_time(dead_there, fs::file_time_type::clock::now() - foreign_temporary_age -
                                      std::chrono::minutes(1));
  const auto removed = remove_stale_temporaries(dir_);
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_EQ(removed[0], dead_there);
  EXPECT_TRUE(fs::exists(live_there)) << "a recently written temporary of another machine removed";
}

TEST_F(TempRegistryTest, RegisterAndUnregister) {
  const auto before = registered_temporaries();
  const int slot = register_temporary(dir_ / "a.tmp-1");
  ASSERT_GE(slot, 0);
  EXPECT_EQ(registered_temporaries(), before + 1);
  unregister_temporary(slot);
  EXPECT_EQ(registered_temporaries(), before);
  unregister_temporary(-1);  // harmless
}

TEST_F(TempRegistryTest, AtomicFileRegistersItsTemporaryUntilCommit) {
  const auto before = registered_temporaries();
  {
    AtomicFile f(dir_ / "a.csv");
    EXPECT_EQ(registered_temporaries(), before + 1);
    f.write("x");
    f.commit();
    EXPECT_EQ(registered_temporaries(), before);
  }
  {
    AtomicFile f(dir_ / "b.csv");
    EXPECT_EQ(registered_temporaries(), before + 1);
  }
  EXPECT_EQ(registered_temporaries(), before);
}

// A child writing a file atomically is sent `sig`: it must die of that signal
// and leave no temporary.
void expect_cleanup_on(int sig, const fs::path& dir) {
  const auto target = dir / "data.csv";
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(ready[0]);
    install_temporary_cleanup();
    AtomicFile f(target);
    f.write("partial");
    (void)!::write(ready[1], "r", 1);
    for (;;) ::pause();
  }
  ::close(ready[1]);
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  ::close(ready[0]);
  const auto temporary = dir / ("data.csv" + temporary_suffix(child));
  EXPECT_TRUE(fs::exists(temporary));
  ::kill(child, sig);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the signal's default action must still end the process";
  EXPECT_EQ(WTERMSIG(status), sig);
  EXPECT_FALSE(fs::exists(temporary)) << "temporary left behind after signal " << sig;
  EXPECT_FALSE(fs::exists(target));
}

TEST_F(TempRegistryTest, SigtermRemovesTemporaries) { expect_cleanup_on(SIGTERM, dir_); }
TEST_F(TempRegistryTest, SigintRemovesTemporaries) { expect_cleanup_on(SIGINT, dir_); }

}  // namespace
}  // namespace epviz::io
