// Many pages at once, several of them 3840x2160: every connection keeps a
// frame rate, because the render thread serves them round-robin and a
// round's pixels are bounded (large views are rendered smaller, all alike).
#include <gtest/gtest.h>

#include <algorithm>

#include "serve_test_support.hpp"

namespace epviz::serve::testing {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

// The longest a page waited for a frame between from and to (from `from` to its first one included).
double longest_wait(std::vector<Clock::time_point> times, Clock::time_point from,
                    Clock::time_point to) {
  std::erase_if(times, [&](auto t) { return t < from || t > to; });
  if (times.empty()) return std::chrono::duration<double>(to - from).count();
  double longest = std::chrono::duration<double>(times.front() - from).count();
  for (std::size_t k = 1; k < times.size(); ++k)
    longest = std::max(longest, std::chrono::duration<double>(times[k] - times[k - 1]).count());
  return longest;
}

TEST(ServeFairness, TwelveClientsFourOfThemLargeAllKeepAFrameRate) {
  constexpr long budget = 3840L * 2160;
  TestServer server([](ServerOptions& o) { o.pixel_budget = budget; }, /*always_wants=*/true);
  // 100 ms per megapixel: a full 3840x2160 frame costs ~0.8 s more than its
  // real work, so four of them a round leave every page waiting four full
  // frames for each of its own; a fair round costs one full frame's pixels
  // plus twelve small frames.
  server.probe->render_ms_per_megapixel = 100;
  // The yardstick, measured here rather than assumed: the time between frames
  // of one page alone at full size. The sanitizers and a busy machine slow
  // the real work, and so this, alike.
  double full_frame = 0;
  {
    ReadingPage alone(server.port(), 3840, 2160);
    ASSERT_TRUE(TestServer::eventually([&] { return alone.arrivals().size() >= 4; }))
        << "a page alone got no frame rate";
    const std::vector<Clock::time_point> times = alone.arrivals();
    full_frame = std::chrono::duration<double>(times[3] - times[1]).count() / 2;
  }
  std::vector<std::unique_ptr<ReadingPage>> viewers;
  for (int i = 0; i < 12; ++i) {
    const bool large = i % 3 == 0;
    viewers.push_back(
        std::make_unique<ReadingPage>(server.port(), large ? 3840 : 320 + i, large ? 2160 : 240));
  }
  // Every page has its first frame soon...
  ASSERT_TRUE(TestServer::eventually([&] {
    return std::all_of(viewers.begin(), viewers.end(),
                       [](const auto& v) { return !v->arrivals().empty(); });
  })) << "a page got no frame at all";
  // ...and then never waits long for the next.
  const Clock::time_point from = Clock::now();
  std::this_thread::sleep_for(std::chrono::duration<double>(10 * full_frame));
  const Clock::time_point to = Clock::now();
  for (std::size_t i = 0; i < viewers.size(); ++i) {
    SCOPED_TRACE("viewer " + std::to_string(i));
    // Between fair rounds (a page waits one or two of them, each one full
    // frame's pixels: measured up to 2.1 full frames) and an unfair one (four
    // full frames: measured 4.1, unbudgeted).
    EXPECT_LT(longest_wait(viewers[i]->arrivals(), from, to), 3 * full_frame)
        << "a page waited this long (s) for a frame; one full frame takes " << full_frame << " s";
  }
  // The large views were scaled alike, keeping their shape, within the budget.
  const auto [w, h] = viewers[0]->last_size();
  EXPECT_LT(w, 3840);
  EXPECT_NEAR(double(w) / h, 3840.0 / 2160.0, 0.01);
  long total = 0;
  for (const auto& v : viewers) total += long(v->last_size().first) * v->last_size().second;
  EXPECT_LE(total, budget);
  EXPECT_GT(server.server->stats().downscaled_frames, 0);
}

TEST(ServeFairness, ViewsWithinTheBudgetAreNotScaled) {
  TestServer server([](ServerOptions& o) { o.pixel_budget = 100 * 100 * 2; });
  TestClient a(server.port()), b(server.port());
  a.send(resize(100, 100));
  b.send(resize(100, 100));
  for (TestClient* c : {&a, &b}) {
    const std::optional<ServerMessage> frame = c->receive();
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->header["width"], 100);
    EXPECT_EQ(frame->header["height"], 100);
  }
  EXPECT_EQ(server.server->stats().downscaled_frames, 0);
}

}  // namespace
}  // namespace epviz::serve::testing
