// Where a frame's time goes: the stage times in each frame header and the
// medians `GET /stats` reports, from the render thread (simulate, draw, read
// back, encode) and the network thread (queue, send).
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "http_test_support.hpp"
#include "serve/stage_times.hpp"
#include "serve_test_support.hpp"

namespace epviz::serve::testing {
namespace {

using nlohmann::json;

ServerMessage next_frame(TestClient& client) {
  std::optional<ServerMessage> m = client.receive();
  if (!m || m->header.value("kind", "") != "frame")
    throw std::runtime_error("no frame arrived within the deadline");
  return *m;
}

json move(int seq) { return {{"type", "move"}, {"x", 1}, {"y", 2}, {"seq", seq}}; }

// Nearest-rank quantile, written out independently of StageTimes.
double nearest_rank(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  std::size_t rank = 1;
  while (double(rank) < q * double(v.size())) ++rank;
  return v[rank - 1];
}

TEST(ServeStageTimes, SummaryIsOverTheNewestWindowOfSamples) {
  StageTimes times;
  std::vector<double> newest;
  const std::size_t total = StageTimes::window + 137;
  for (std::size_t i = 0; i < total; ++i) {
    // Descending then rising, so that keeping the oldest instead would change the figures.
    const double ms = i < 300 ? 1000.0 - double(i) : double(i % 97) * 0.5;
    times.record(Stage::encode, ms);
    if (i >= total - StageTimes::window) newest.push_back(ms);
  }
  times.record(Stage::send, 4.0);
  const json s = times.summary();
  EXPECT_EQ(s["encode"]["samples"], StageTimes::window);
  EXPECT_DOUBLE_EQ(s["encode"]["median_ms"].get<double>(), nearest_rank(newest, 0.5));
  EXPECT_DOUBLE_EQ(s["encode"]["p90_ms"].get<double>(), nearest_rank(newest, 0.9));
  EXPECT_EQ(s["send"]["samples"], 1);
  EXPECT_DOUBLE_EQ(s["send"]["median_ms"].get<double>(), 4.0);
  // Every stage is listed, the ones with no sample without figures.
  for (const char* name : {"simulate", "draw", "read_back", "queue"}) {
    EXPECT_EQ(s[name]["samples"], 0) << name;
    EXPECT_FALSE(s[name].contains("median_ms")) << name;
  }
}

TEST(ServeStageTimes, FrameHeadersCarryTheSessionsStages) {
  TestServer server;
  server.probe->reports_stages = true;
  TestClient client(server.port());
  client.send(resize(32, 16));
  const json h = next_frame(client).header;
  EXPECT_DOUBLE_EQ(h["simulate_ms"].get<double>(), fake_stages.simulate_ms);
  EXPECT_DOUBLE_EQ(h["draw_ms"].get<double>(), fake_stages.draw_ms);
  EXPECT_DOUBLE_EQ(h["read_back_ms"].get<double>(), fake_stages.read_back_ms);
  EXPECT_GT(h["encode_ms"].get<double>(), 0.0);
}

TEST(ServeStageTimes, ASessionThatTellsNoStagesHasItsRenderCountedAsDraw) {
  TestServer server;
  server.probe->render_ms_per_megapixel = 20'000;  // some 10 ms for 32 x 16
  TestClient client(server.port());
  client.send(resize(32, 16));
  const json h = next_frame(client).header;
  EXPECT_DOUBLE_EQ(h["draw_ms"].get<double>(), h["render_ms"].get<double>());
  EXPECT_GE(h["draw_ms"].get<double>(), 10.0);
  EXPECT_EQ(h["simulate_ms"], 0.0);
  EXPECT_EQ(h["read_back_ms"], 0.0);
}

TEST(ServeStageTimes, AFramesHeaderHasTheQueueAndSendTimesOfTheFrameWrittenBefore) {
  // One frame in flight: frame 2 is rendered only after frame 1's write completed.
  TestServer server([](ServerOptions& o) { o.max_frames_in_flight = 1; });
  TestClient client(server.port());
  client.send(resize(32, 16));
  const json first = next_frame(client).header;
  EXPECT_FALSE(first.contains("written")) << first.dump();
  client.send(ack(1));
  client.send(move(1));
  const json second = next_frame(client).header;
  ASSERT_TRUE(second.contains("written")) << second.dump();
  EXPECT_EQ(second["written"]["frame"], 1);
  EXPECT_GE(second["written"]["queue_ms"].get<double>(), 0.0);
  EXPECT_GE(second["written"]["send_ms"].get<double>(), 0.0);
}

TEST(ServeStageTimes, StatsEndpointReportsEveryStage) {
  TestServer server;
  server.probe->reports_stages = true;
  TestClient client(server.port());
  client.send(resize(32, 16));
  constexpr int frames = 5;
  for (int i = 1; i <= frames; ++i) {
    EXPECT_EQ(next_frame(client).header["frame"], i);
    client.send(ack(i));
    if (i < frames) client.send(move(i));
  }
  // Queue and send are noted when a write completes, which may be just after the page read it.
  json stats;
  ASSERT_TRUE(TestServer::eventually([&] {
    const auto response = http_get(server.port(), "/stats");
    if (response.result() != boost::beast::http::status::ok) return false;
    EXPECT_EQ(response[boost::beast::http::field::content_type], "application/json");
    stats = json::parse(response.body());
    return stats["stages"]["send"]["samples"].get<int>() >= frames;
  })) << stats.dump();
  EXPECT_EQ(stats["frames_sent"], frames);
  const json& st = stats["stages"];
  for (const char* name : {"simulate", "draw", "read_back", "encode", "queue", "send"})
    EXPECT_EQ(st[name]["samples"], frames) << name;
  EXPECT_DOUBLE_EQ(st["draw"]["median_ms"].get<double>(), fake_stages.draw_ms);
  EXPECT_DOUBLE_EQ(st["simulate"]["p90_ms"].get<double>(), fake_stages.simulate_ms);
  EXPECT_DOUBLE_EQ(st["read_back"]["median_ms"].get<double>(), fake_stages.read_back_ms);
  EXPECT_GE(st["queue"]["median_ms"].get<double>(), 0.0);
}

}  // namespace
}  // namespace epviz::serve::testing
