// Atomic writes replace regular files only: streams (device nodes, FIFOs,
// standard output) are written directly, symbolic links are followed.
#include "io/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <string>
#include <thread>

#include "support/temp_dir.hpp"

namespace epviz::io {
namespace {

namespace fs = std::filesystem;

using AtomicFileTest = test::TempDirTest;

TEST_F(AtomicFileTest, RegularAndMissingFilesAreReplaced) {
  std::ofstream(dir_ / "old.csv") << "old";
  const auto regular = resolve_output(dir_ / "old.csv");
  EXPECT_EQ(regular.kind, OutputKind::replace);
  EXPECT_EQ(regular.path, dir_ / "old.csv");
  const auto missing = resolve_output(dir_ / "new.csv");
  EXPECT_EQ(missing.kind, OutputKind::replace);
  EXPECT_EQ(missing.path, dir_ / "new.csv");
}

TEST_F(AtomicFileTest, DashIsStandardOutput) {
  EXPECT_EQ(resolve_output("-").kind, OutputKind::standard_output);
  EXPECT_TRUE(writes_to_standard_output("-"));
  EXPECT_FALSE(writes_to_standard_output(dir_ / "x.csv"));
}

TEST_F(AtomicFileTest, DeviceNodesAndFifosAreStreams) {
  EXPECT_EQ(resolve_output("/dev/null").kind, OutputKind::stream);
  EXPECT_EQ(resolve_output("/dev/zero").kind, OutputKind::stream);  // another character device
  EXPECT_EQ(resolve_output("/dev/full").kind, OutputKind::stream);
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  EXPECT_EQ(resolve_output(dir_ / "fifo").kind, OutputKind::stream);
  // /dev/stdout names a file descriptor through /proc: never a name to replace.
  if (fs::is_symlink("/dev/stdout")) {
    EXPECT_EQ(resolve_output("/dev/stdout").kind, OutputKind::stream);
  }
}

TEST_F(AtomicFileTest, SymbolicLinksAreFollowedToTheRealFile) {
  fs::create_directories(dir_ / "real");
  fs::create_directories(dir_ / "links");
  std::ofstream(dir_ / "real" / "data.csv") << "old";
  fs::create_symlink(dir_ / "real" / "data.csv", dir_ / "links" / "hop2");
  fs::create_symlink("hop2", dir_ / "links" / "data.csv");  // relative, two hops
  const auto r = resolve_output(dir_ / "links" / "data.csv");
  EXPECT_EQ(r.kind, OutputKind::replace);
  EXPECT_EQ(fs::weakly_canonical(r.path), fs::weakly_canonical(dir_ / "real" / "data.csv"));

  {
    AtomicFile f(dir_ / "links" / "data.csv");
    // The temporary lies beside the real file, so the rename stays on its file system.
    EXPECT_TRUE(fs::exists(temporary_path_for(dir_ / "real" / "data.csv")));
    EXPECT_FALSE(fs::exists(temporary_path_for(dir_ / "links" / "data.csv")));
    f.write("new");
    f.commit();
  }
  EXPECT_TRUE(fs::is_symlink(dir_ / "links" / "data.csv")) << "the link must stay a link";
  EXPECT_EQ(test::slurp(dir_ / "real" / "data.csv"), "new");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "real"), {}), 1);
}

TEST_F(AtomicFileTest, DanglingLinkCreatesItsTarget) {
  fs::create_symlink(dir_ / "target.csv", dir_ / "link.csv");
  write_file_atomically(dir_ / "link.csv", "x");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.csv"));
  EXPECT_EQ(test::slurp(dir_ / "target.csv"), "x");
}

TEST_F(AtomicFileTest, LinkLoopIsAClearError) {
  fs::create_symlink(dir_ / "b", dir_ / "a");
  fs::create_symlink(dir_ / "a", dir_ / "b");
  EXPECT_THROW(resolve_output(dir_ / "a"), FileWriteError);
}

TEST_F(AtomicFileTest, DevNullIsWrittenNotReplaced) {
  struct stat before {};
  ASSERT_EQ(::stat("/dev/null", &before), 0);
  write_file_atomically("/dev/null", "discarded");
  struct stat after {};
  ASSERT_EQ(::stat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(before.st_ino, after.st_ino);
  EXPECT_FALSE(fs::exists(temporary_path_for("/dev/null")));
}

TEST_F(AtomicFileTest, DevFullGivesAWriteError) {
  try {
    write_file_atomically("/dev/full", std::string(1 << 16, 'x'));
    FAIL() << "no error writing to /dev/full";
  } catch (const FileWriteError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/dev/full"), std::string::npos) << what;
    EXPECT_NE(what.find("No space left"), std::string::npos) << what;
  }
}

TEST_F(AtomicFileTest, FifoIsWrittenAsAStream) {
  const auto fifo = dir_ / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = test::slurp(fifo); });
  write_file_atomically(fifo, "row 1\nrow 2\n");
  reader.join();
  EXPECT_EQ(received, "row 1\nrow 2\n");
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced";
}

TEST_F(AtomicFileTest, StandardOutputIsWrittenInPlace) {
  // A child with its standard output on a file writes "-" there.
  const auto out = dir_ / "out.txt";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::FILE* f = std::freopen(out.c_str(), "w", stdout);
    if (!f) ::_exit(10);
    try {
      write_file_atomically("-", "to stdout\n");
    } catch (...) {
      ::_exit(11);
    }
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(test::slurp(out), "to stdout\n");
  EXPECT_FALSE(fs::exists("-"));
}

}  // namespace
}  // namespace epviz::io
