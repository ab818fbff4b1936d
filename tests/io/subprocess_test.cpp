// io::Subprocess: arguments reach the child verbatim (no shell), stdin and
// stdout round-trip through pipes (also more than a pipe holds), exit codes and
// signals are reported, and writing to a child that has exited returns EPIPE
// instead of killing this process with SIGPIPE.
#include <gtest/gtest.h>

#include <signal.h>

#include <cerrno>
#include <string>

#include "io/subprocess.hpp"

namespace epviz::io {
namespace {

TEST(Subprocess, CatRoundTripsStdin) {
  const auto r = run_process({"cat"}, "hello\nworld\n");
  EXPECT_TRUE(r.status.success()) << r.status.describe();
  EXPECT_EQ(r.out, "hello\nworld\n");
  EXPECT_EQ(r.err, "");
}

TEST(Subprocess, RoundTripLargerThanAPipe) {
  // 4 MB each way: writing it all before reading would deadlock on a 64 kB pipe.
  std::string input(4 << 20, '\0');
  for (std::size_t i = 0; i < input.size(); ++i) input[i] = char('a' + i % 26);
  const auto r = run_process({"cat"}, input);
  EXPECT_TRUE(r.status.success());
  EXPECT_EQ(r.out.size(), input.size());
  EXPECT_TRUE(r.out == input);
}

TEST(Subprocess, ArgumentsAreNotInterpretedByAShell) {
  const auto r = run_process({"printf", "%s|%s", "a b; echo x", "$HOME *"});
  EXPECT_TRUE(r.status.success());
  EXPECT_EQ(r.out, "a b; echo x|$HOME *");
}

TEST(Subprocess, ExitStatusAndStderr) {
  const auto r = run_process({"sh", "-c", "echo oops >&2; exit 3"});
  EXPECT_TRUE(r.status.exited());
  EXPECT_EQ(r.status.code(), 3);
  EXPECT_FALSE(r.status.success());
  EXPECT_EQ(r.status.describe(), "exited with status 3");
  EXPECT_EQ(r.err, "oops\n");
}

TEST(Subprocess, KilledChildIsReportedAsSignalled) {
  Subprocess child({"sleep", "30"});
  child.kill(SIGTERM);
  const auto s = child.wait();
  EXPECT_TRUE(s.signalled());
  EXPECT_EQ(s.signal(), SIGTERM);
  EXPECT_FALSE(s.success());
  EXPECT_EQ(child.wait().raw, s.raw);  // waiting again gives the same status
}

TEST(Subprocess, MissingProgramThrowsWithEnoent) {
  try {
    Subprocess child({"/nonexistent/epviz-no-such-program"});
    FAIL() << "started a missing program";
  } catch (const SubprocessError& e) {
    EXPECT_EQ(e.errno_value, ENOENT);
    EXPECT_NE(std::string(e.what()).find("epviz-no-such-program"), std::string::npos) << e.what();
  }
}

TEST(Subprocess, ChildExitingEarlyDoesNotKillUsWithSigpipe) {
  // SIGPIPE at its default action would end this test process here.
  struct sigaction old {};
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigaction(SIGPIPE, &dfl, &old);
  Subprocess child({"head", "-c", "1"}, {.in = Subprocess::Stream::pipe,
                                         .out = Subprocess::Stream::null,
                                         .err = Subprocess::Stream::null});
  const std::string chunk(1 << 16, 'x');
  int error = 0;
  for (int i = 0; i < 1000 && error == 0; ++i)
    error = child.write_stdin(chunk.data(), chunk.size());
  EXPECT_EQ(error, EPIPE);
  EXPECT_TRUE(child.wait().success());
  // communicate() on a child that reads nothing is just as safe.
  Subprocess deaf({"true"});
  std::string out, err;
  const int write_error = deaf.communicate(std::string(1 << 20, 'y'), out, err);
  EXPECT_TRUE(write_error == 0 || write_error == EPIPE) << write_error;
  EXPECT_TRUE(deaf.wait().success());
  sigaction(SIGPIPE, &old, nullptr);
}

}  // namespace
}  // namespace epviz::io
