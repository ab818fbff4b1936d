// Adaptive resolution (ServerOptions::frame_budget_ms): frames that cost
// more than the budget (to draw and encode, or for the page to decode) make
// the view render smaller, never below
// min_detail; at rest it is rendered once more at full size; the page's
// positions are scaled to the size the session renders.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <stdexcept>

#include "serve_test_support.hpp"

namespace epviz::serve::testing {
namespace {

using nlohmann::json;

constexpr int kWidth = 64, kHeight = 48;

ServerMessage next_frame(TestClient& client) {
  std::optional<ServerMessage> m = client.receive();
  if (!m || m->header.value("kind", "") != "frame")
    throw std::runtime_error("no frame arrived within the deadline");
  return *m;
}

json move_to(int seq, float x, float y) {
  return {{"type", "move"}, {"x", x}, {"y", y}, {"seq", seq}};
}

// Options with a budget of `budget_ms`, and how long a view must rest before it is sharpened.
std::function<void(ServerOptions&)> budget(double budget_ms,
                                           std::chrono::milliseconds rest = 250ms) {
  return [budget_ms, rest](ServerOptions& o) {
    o.frame_budget_ms = budget_ms;
    o.min_detail = 0.5;
    o.rest_before_sharpening = rest;
  };
}

// A page of kWidth x kHeight on a server with `options`, whose sessions take
// about 40 ms for a full frame (sleeping, so whatever the machine's load).
struct SlowPage {
  SlowPage(const std::function<void(ServerOptions&)>& options, bool always_wants)
      : server(options, always_wants), client(server.port()) {
    server.probe->render_ms_per_megapixel = 13'000;
    client.send(resize(kWidth, kHeight));
  }
  // The next frame's header, acknowledged as the page does once it is shown.
  json shown() {
    const json h = next_frame(client).header;
    client.send(ack(h["frame"].get<std::int64_t>()));
    return h;
  }
  TestServer server;
  TestClient client;
};

// Reads and acks frames until one is narrower than the page's view; its header.
std::optional<json> first_reduced_frame(SlowPage& page, int max_frames, int& seq, bool send_input) {
  for (int i = 0; i < max_frames; ++i) {
    const json h = page.shown();
    if (h["width"].get<int>() < kWidth) return h;
    if (send_input) page.client.send(move_to(++seq, 10, 10));
  }
  return std::nullopt;
}

TEST(ServeAdaptiveDetail, FramesOverTheBudgetAreRenderedSmallerButNotBelowTheMinimum) {
  SlowPage page(budget(10.0), true);
  int seq = 0;
  const auto reduced = first_reduced_frame(page, 12, seq, false);
  ASSERT_TRUE(reduced) << "the view stayed full size although every frame cost four budgets";
  // The shape is kept, and a size change is its own frame's size.
  EXPECT_NEAR(double((*reduced)["height"]) / kHeight, double((*reduced)["width"]) / kWidth, 0.05);
  for (int i = 0; i < 20; ++i) {
    const json h = page.shown();
    EXPECT_GE(h["width"].get<int>(), kWidth / 2) << h.dump();
    EXPECT_GE(h["height"].get<int>(), kHeight / 2) << h.dump();
  }
  EXPECT_GT(page.server.server->stats().downscaled_frames, 0);
  // The session was told its scale, to draw its interface to match.
  EXPECT_LT(page.server.probe->view_scale.load(), 1.0);
}

// A page whose frames the server draws at once but which reports taking
// `decode_ms` to decode each: the frame rate is the page's to limit.
int narrowest_width_with_page_decoding(double decode_ms, int frames) {
  TestServer server(budget(10.0), true);
  server.probe->render_ms_per_megapixel = 0;
  TestClient client(server.port());
  client.send(resize(kWidth, kHeight));
  int narrowest = kWidth;
  for (int i = 0; i < frames; ++i) {
    const json h = next_frame(client).header;
    narrowest = std::min(narrowest, h["width"].get<int>());
    client.send({{"type", "ack"}, {"frame", h["frame"]}, {"decode_ms", decode_ms}});
  }
  return narrowest;
}

TEST(ServeAdaptiveDetail, APageThatDecodesSlowlyGetsSmallerFramesOneThatDecodesFastDoesNot) {
  EXPECT_LT(narrowest_width_with_page_decoding(40.0, 16), kWidth)
      << "frames cheap to draw but four budgets to decode stayed full size";
  EXPECT_EQ(narrowest_width_with_page_decoding(1.0, 16), kWidth)
      << "frames cheap to draw and to decode were made smaller";
}

TEST(ServeAdaptiveDetail, WithoutABudgetTheViewStaysFullSize) {
  SlowPage page(budget(0.0), true);
  for (int i = 0; i < 12; ++i) {
    EXPECT_EQ(page.shown()["width"], kWidth);
  }
}

TEST(ServeAdaptiveDetail, AtRestTheViewIsRenderedSharpAndInputIsScaledToTheSessionsSize) {
  SlowPage page(budget(10.0), false);
  TestClient& client = page.client;
  int seq = 0;
  // Moving: every frame answers an input, until the view is rendered smaller.
  const auto reduced = first_reduced_frame(page, 12, seq, true);
  ASSERT_TRUE(reduced);
  int small_width = (*reduced)["width"], small_height = (*reduced)["height"];
  // No more input: soon the view comes at full size, unasked.
  json sharp;
  for (int i = 0; i < 6; ++i) {
    sharp = page.shown();
    if (sharp["width"] == kWidth) break;
    small_width = sharp["width"];
    small_height = sharp["height"];
  }
  ASSERT_EQ(sharp["width"], kWidth) << sharp.dump();
  ASSERT_EQ(sharp["height"], kHeight);
  EXPECT_DOUBLE_EQ(page.server.probe->view_scale.load(), 1.0);
  // Moving again, from the sharp frame the page shows: the session is back
  // at the smaller size, and the position is in its pixels.
  const ServerMessage after = [&] {
    client.send(move_to(++seq, 40.0f, 30.0f));
    return next_frame(client);
  }();
  EXPECT_EQ(after.header["width"], small_width);
  EXPECT_NEAR(page.server.probe->last_x.load(), 40.0 * small_width / kWidth, 1e-3);
  EXPECT_NEAR(page.server.probe->last_y.load(), 30.0 * small_height / kHeight, 1e-3);
}

TEST(ServeAdaptiveDetail, APauseShorterThanTheRestIsNotSharpened) {
  SlowPage page(budget(10.0, 60s), false);
  TestClient& client = page.client;
  int seq = 0;
  ASSERT_TRUE(first_reduced_frame(page, 12, seq, true));
  // Frames already asked for may still come; then nothing, for far less than a minute.
  std::optional<ServerMessage> m;
  while ((m = client.receive(quiet_period))) {
    client.send(ack(m->header["frame"].get<std::int64_t>()));
    EXPECT_LT(m->header["width"].get<int>(), kWidth) << "sharpened before the rest was over";
  }
}

}  // namespace
}  // namespace epviz::serve::testing
