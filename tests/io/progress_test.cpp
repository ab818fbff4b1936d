#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <sstream>
#include <string>

#include "io/progress.hpp"

namespace {

using namespace epviz::io;
using Clock = std::chrono::steady_clock;

struct FakeClock {
  Clock::time_point t = Clock::time_point(std::chrono::seconds(1000));
  void advance(double seconds) {
    t += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  }
};

// A progress line shown as on a terminal, written to `out`, on `clock`'s time.
ProgressOptions shown(std::ostream& out, FakeClock& clock) {
  ProgressOptions options;
  options.mode = ProgressMode::on;
  options.out = &out;
  options.clock = [&clock] { return clock.t; };
  return options;
}

std::size_t count(const std::string& s, char c) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), c));
}

TEST(Progress, TerminalLineShowsDoneTotalRateAndEtaAndEndsWithNewline) {
  std::ostringstream out;
  FakeClock clock;
  ProgressOptions options = shown(out, clock);
  options.label = "euler";
  {
    ProgressLine progress(100, options);
    EXPECT_TRUE(progress.enabled());
    for (int i = 0; i < 50; ++i) {
      clock.advance(0.02);  // 50 frames/s
      progress.advance();
    }
    const std::string middle = out.str();
    // The last draw before frame 50 (draws are throttled to one per 0.2 s).
    EXPECT_NE(middle.find("euler: 41/100 frames, 50.0 frames/s, ETA 0:02"), std::string::npos)
        << middle;
    EXPECT_EQ(middle.front(), '\r');
    EXPECT_EQ(count(middle, '\n'), 0u);
    // Throttled: one draw at the first frame, then at most one per 0.2 s of the 1 s elapsed.
    EXPECT_LE(count(middle, '\r'), 7u);
    EXPECT_GE(count(middle, '\r'), 5u);
    for (int i = 0; i < 50; ++i) {
      clock.advance(0.02);
      progress.advance();
    }
    progress.finish();
    progress.finish();  // once only
  }
  const std::string all = out.str();
  EXPECT_NE(all.find("100/100 frames, 50.0 frames/s, ETA 0:00"), std::string::npos) << all;
  EXPECT_EQ(all.back(), '\n');
  EXPECT_EQ(count(all, '\n'), 1u);
}

TEST(Progress, ShorterLineBlanksTheRestOfTheLongerOne) {
  std::ostringstream out;
  FakeClock clock;
  ProgressOptions options = shown(out, clock);
  options.min_interval = std::chrono::duration<double>(0);
  ProgressLine progress(10, options);
  progress.update(0);  // "--" rate, "--:--" ETA
  clock.advance(1.0);
  progress.update(1);
  const std::string s = out.str();
  const std::size_t second = s.find('\r', 1);
  ASSERT_NE(second, std::string::npos);
  EXPECT_NE(s.find("0/10 frames, -- frames/s, ETA --:--"), std::string::npos) << s;
  EXPECT_NE(s.find("1/10 frames, 1.0 frames/s, ETA 0:09"), std::string::npos) << s;
  EXPECT_GE(s.size() - second, second) << "the second draw covers the first";
}

TEST(Progress, ResumedFramesDoNotCountInTheRate) {
  std::ostringstream out;
  FakeClock clock;
  ProgressOptions options = shown(out, clock);
  options.already_done = 90;
  ProgressLine progress(100, options);
  clock.advance(1.0);
  progress.update(95);
  EXPECT_NE(out.str().find("95/100 frames, 5.0 frames/s, ETA 0:01"), std::string::npos)
      << out.str();
}

TEST(Progress, NotATerminalWritesNothing) {
  std::ostringstream out;
  ProgressOptions options;
  options.mode = ProgressMode::off;
  options.out = &out;
  {
    ProgressLine progress(10, options);
    EXPECT_FALSE(progress.enabled());
    for (int i = 0; i < 10; ++i) progress.advance();
    progress.finish();
  }
  EXPECT_TRUE(out.str().empty());
}

TEST(Progress, AutomaticFollowsWhetherStderrIsATerminal) {
  std::ostringstream out;
  ProgressOptions options;
  options.out = &out;
  {
    ProgressLine progress(3, options);
    EXPECT_EQ(progress.enabled(), ::isatty(STDERR_FILENO) == 1);
    progress.advance(3);
  }
  if (::isatty(STDERR_FILENO) != 1) {
    EXPECT_TRUE(out.str().empty());
  }
}

TEST(Progress, EtaFormat) {
  EXPECT_EQ(format_eta(0), "0:00");
  EXPECT_EQ(format_eta(6.2), "0:07");
  EXPECT_EQ(format_eta(725), "12:05");
  EXPECT_EQ(format_eta(3723), "1:02:03");
  EXPECT_EQ(format_eta(-1), "--:--");
  EXPECT_EQ(format_progress("", 3, 4, 2.5, 0.4), "3/4 frames, 2.5 frames/s, ETA 0:01");
}

}  // namespace
