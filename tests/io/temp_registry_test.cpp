// Temporaries are removed on SIGINT/SIGTERM, and stale ones of dead processes
// on the next run.
#include "io/temp_registry.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>

#include "io/atomic_file.hpp"
#include "support/dead_pid.hpp"
#include "support/temp_dir.hpp"

namespace epviz::io {
namespace {

namespace fs = std::filesystem;

using TempRegistryTest = test::TempDirTest;

using test::dead_pid;

TEST(TemporaryName, ParsesOnlyTheTemporaryShape) {
  pid_t pid = 0;
  EXPECT_TRUE(parse_temporary_name("a.mp4.tmp-1234", pid));
  EXPECT_EQ(pid, 1234);
  EXPECT_FALSE(parse_temporary_name("a.mp4", pid));
  EXPECT_FALSE(parse_temporary_name("a.tmp-", pid));
  EXPECT_FALSE(parse_temporary_name("a.tmp-12x", pid));
  EXPECT_FALSE(parse_temporary_name(".tmp-12", pid));
  EXPECT_FALSE(parse_temporary_name("a.tmp-0", pid));
}

TEST_F(TempRegistryTest, StaleTemporariesOfDeadProcessesAreRemoved) {
  const pid_t dead = dead_pid();
  const pid_t live = ::getppid();  // the test runner's parent is alive
  const auto stale = dir_ / ("x.mp4.tmp-" + std::to_string(dead));
  const auto busy = dir_ / ("y.mp4.tmp-" + std::to_string(live));
  const auto ours = dir_ / ("z.csv.tmp-" + std::to_string(::getpid()));
  const auto unrelated = dir_ / "notes.txt";
  for (const auto& p : {stale, busy, ours, unrelated}) std::ofstream(p) << "x";
  fs::create_directories(dir_ / ("d.tmp-" + std::to_string(dead)));  // not a file: kept

  const auto removed = remove_stale_temporaries(dir_);
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_EQ(removed[0], stale);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(busy));
  EXPECT_TRUE(fs::exists(ours));
  EXPECT_TRUE(fs::exists(unrelated));
  EXPECT_TRUE(fs::exists(dir_ / ("d.tmp-" + std::to_string(dead))));
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
  const auto temporary = dir / ("data.csv.tmp-" + std::to_string(child));
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
