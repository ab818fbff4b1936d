// The frame server end to end over real sockets, with fake sessions: frames
// after resize and input, flow control, robustness against bad or vanishing
// clients, client limits, the page over HTTP, start and stop.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <future>

#include <unistd.h>

#include "http_test_support.hpp"
#include "serve/shared_state.hpp"
#include "serve_test_support.hpp"

namespace epviz::serve::testing {
namespace {

namespace http = boost::beast::http;
using nlohmann::json;

json move(int seq) { return {{"type", "move"}, {"x", 3}, {"y", 4}, {"seq", seq}}; }
json key(const std::string& name) { return {{"type", "key"}, {"key", name}, {"down", true}}; }

// The next message, which must be a frame (throws otherwise: gtest reports it).
ServerMessage frame_from(TestClient& client) {
  std::optional<ServerMessage> m = client.receive();
  if (!m) throw std::runtime_error("no frame arrived within the deadline");
  if (m->header.value("kind", "") != "frame")
    throw std::runtime_error("expected a frame, got " + m->header.dump());
  return std::move(*m);
}

void expect_colour(const ServerMessage& frame, glm::u8vec4 want) {
  const render::RgbaImage image = decode_jpeg(frame.payload);
  const glm::u8vec4 got = image.at(image.width / 2, image.height / 2);
  for (int c = 0; c < 3; ++c)
    EXPECT_LE(std::abs(int(got[c]) - int(want[c])), 6)
        << "channel " << c << " of frame " << frame.header.dump();
}

// A page at 32 x 32 that has its first frame and acked it: the fake session
// then wants no frame until the next input.
void settle(TestClient& client) {
  client.send(resize(32, 32));
  EXPECT_EQ(frame_from(client).header["frame"], 1);
  client.send(ack(1));
}

// Asserts that the bystander still gets frames for its input: ack what it
// has, send input with `seq`, and see a frame carrying that seq.
void expect_still_served(TestClient& bystander, std::int64_t acked, int seq) {
  bystander.send(ack(acked));
  bystander.send(move(seq));
  for (;;) {  // an always-wanting session may send frames rendered before the input
    const ServerMessage frame = frame_from(bystander);
    bystander.send(ack(frame.header["frame"].get<std::int64_t>()));
    if (frame.header["seq"] == seq) return;
  }
}

TEST(ServeServer, FrameAfterResizeThenInputChangesTheFrame) {
  TestServer server;
  // The fake session sleeps about 40 ms (at least that long) to render 64 x 48 pixels.
  constexpr int ms_per_megapixel = 13'000;
  const double render_sleep_ms = std::floor(64 * 48 * ms_per_megapixel / 1e3) / 1e3;
  server.probe->render_ms_per_megapixel = ms_per_megapixel;
  TestClient client(server.port());
  const auto asked = std::chrono::steady_clock::now();
  client.send(resize(64, 48));
  const ServerMessage first = frame_from(client);
  const double waited_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - asked).count();
  EXPECT_EQ(first.header["frame"], 1);
  EXPECT_EQ(first.header["seq"], 0);
  EXPECT_EQ(first.header["width"], 64);
  EXPECT_EQ(first.header["height"], 48);
  EXPECT_EQ(first.header["mime"], "image/jpeg");
  // The times the frame reports are the session's render and the encoder's
  // work: the render at least its sleep, the encode some time, both within
  // what the client waited for the frame.
  const double render_ms = first.header["render_ms"].get<double>();
  const double encode_ms = first.header["encode_ms"].get<double>();
  EXPECT_GE(render_ms, render_sleep_ms);
  EXPECT_GT(encode_ms, 0.0);
  EXPECT_LE(render_ms + encode_ms, waited_ms);
  const render::RgbaImage image = decode_jpeg(first.payload);
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
  expect_colour(first, fake_colour(0));

  client.send(ack(1));
  client.send(move(7));
  const ServerMessage second = frame_from(client);
  EXPECT_EQ(second.header["frame"], 2);
  EXPECT_EQ(second.header["seq"], 7);
  expect_colour(second, fake_colour(1));
  EXPECT_EQ(second.header["controls"]["play"], json::array({0, 0, 64, 48}));
  EXPECT_FALSE(server.probe->wrong_thread) << "a session was used off the render thread";
}

TEST(ServeServer, NoFrameBeforeTheFirstResize) {
  TestServer server;
  TestClient client(server.port());
  client.send(move(3));
  EXPECT_FALSE(client.receive(quiet_period)) << "a frame before any resize";
  client.send(resize(32, 32));
  const ServerMessage frame = frame_from(client);
  EXPECT_EQ(frame.header["frame"], 1);
  EXPECT_EQ(frame.header["seq"], 3);  // the input before the resize was applied, not dropped
}

TEST(ServeServer, ResizeIsClampedToTheLimits) {
  TestServer server([](ServerOptions& o) {
    o.max_width = 200;
    o.max_height = 100;
  });
  TestClient client(server.port());
  client.send(resize(5000, 3));
  const ServerMessage frame = frame_from(client);
  EXPECT_EQ(frame.header["width"], 200);
  EXPECT_EQ(frame.header["height"], 16);
}

TEST(ServeServer, RecordsTheFirstConnectionAsItsSessionSawIt) {
  const test::TempDir dir;
  const auto recording = dir / "recording.jsonl";
  TestServer server([&](ServerOptions& o) {
    o.record_path = recording;
    o.max_width = 200;
  });
  TestClient first(server.port());
  first.send(resize(5000, 30));
  frame_from(first);
  TestClient second(server.port());  // not recorded
  second.send(resize(32, 32));
  frame_from(second);
  first.send(ack(1));
  first.send(move(2));
  EXPECT_EQ(frame_from(first).header["seq"], 2);

  std::ifstream in(recording);
  std::vector<json> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(json::parse(line));
  const std::vector<json> expected = {
      resize(200, 30),  // clamped, as the session got it
      {{"type", "render"}},
      move(2),
      {{"type", "render"}},
  };
  EXPECT_EQ(lines, expected);
}

TEST(ServeServer, PngFramesWhenAsked) {
  TestServer server([](ServerOptions& o) { o.image_format = ImageFormat::png; });
  TestClient client(server.port());
  client.send(resize(20, 20));
  const ServerMessage frame = frame_from(client);
  EXPECT_EQ(frame.header["mime"], "image/png");
  ASSERT_GE(frame.payload.size(), 8u);
  EXPECT_EQ(frame.payload[1], 'P');
}

class ServeFlowControl : public ::testing::TestWithParam<int> {};

TEST_P(ServeFlowControl, AtMostMaxFramesInFlight) {
  const int in_flight = GetParam();
  TestServer server([&](ServerOptions& o) { o.max_frames_in_flight = in_flight; },
                    /*always_wants=*/true);
  TestClient client(server.port());
  client.send(resize(32, 32));
  for (int i = 1; i <= in_flight; ++i) EXPECT_EQ(frame_from(client).header["frame"], i);
  EXPECT_FALSE(client.receive(quiet_period))
      << "more than " << in_flight << " frames without an ack";
  EXPECT_EQ(server.probe->renders, in_flight) << "rendered frames that could not be sent";

  client.send(ack(1));  // one slot frees: exactly one more frame
  EXPECT_EQ(frame_from(client).header["frame"], in_flight + 1);
  EXPECT_FALSE(client.receive(quiet_period));

  client.send(ack(in_flight + 1));  // all acknowledged: a full window again
  for (int i = 1; i <= in_flight; ++i)
    EXPECT_EQ(frame_from(client).header["frame"], in_flight + 1 + i);
  EXPECT_FALSE(client.receive(quiet_period));
}

INSTANTIATE_TEST_SUITE_P(Window, ServeFlowControl, ::testing::Values(1, 2, 3));

TEST(ServeServer, AckOfAFrameNeverSentCloses1008) {
  // A page acks frames it has shown; an ack beyond the last frame sent is
  // forged, and counting it would let frames pile up unread.
  TestServer server({}, /*always_wants=*/true);
  TestClient client(server.port());
  client.send(resize(32, 32));
  EXPECT_EQ(frame_from(client).header["frame"], 1);
  EXPECT_EQ(frame_from(client).header["frame"], 2);
  client.send(ack(std::int64_t{1} << 62));
  const std::optional<Closed> closed = client.wait_closed();
  ASSERT_TRUE(closed);
  EXPECT_EQ(closed->code, 1008) << closed->error.message();
  EXPECT_TRUE(server.log->wait_for({"connection #1", "ack for frame", "only 2 frames", "1008"}))
      << server.log->all();
}

TEST(ServeServer, NoFramesWhileTheSessionWantsNone) {
  TestServer server;
  TestClient client(server.port());
  settle(client);
  EXPECT_FALSE(client.receive(quiet_period)) << "a frame the session did not want";
  EXPECT_EQ(server.probe->renders, 1);
  // And the next frame is the one the input asked for, with nothing in between.
  client.send(move(5));
  const ServerMessage frame = frame_from(client);
  EXPECT_EQ(frame.header["frame"], 2);
  EXPECT_EQ(frame.header["seq"], 5);
}

TEST(ServeServer, DownloadsAndNoticesReachThePage) {
  TestServer server;
  TestClient client(server.port());
  settle(client);
  client.send(key("download"));
  client.send(key("notice"));
  bool file = false, notice = false;
  while (!(file && notice)) {
    std::optional<ServerMessage> m = client.receive();
    ASSERT_TRUE(m) << "file " << file << ", notice " << notice;
    const std::string kind = m->header["kind"];
    if (kind == "frame") {
      client.send(ack(m->header["frame"].get<std::int64_t>()));
    } else if (kind == "file") {
      EXPECT_EQ(m->header["name"], "fake.txt");  // directories dropped
      EXPECT_EQ(m->header["mime"], "text/plain");
      EXPECT_EQ(m->payload, (std::vector<std::uint8_t>{'h', 'i'}));
      file = true;
    } else {
      EXPECT_EQ(kind, "notice");
      EXPECT_NE(m->header["text"].get<std::string>().find("notice after"), std::string::npos);
      EXPECT_TRUE(m->payload.empty());
      notice = true;
    }
  }
}

TEST(ServeServer, FloodWhileTheRenderThreadIsBusyLosesNothing) {
  // More events than the inbox holds arrive while the render thread is stuck
  // in input(): the connection stops reading, then resumes once drained.
  // Not many more: the rest wait in the server's TCP receive buffer, where
  // each tiny message costs ~1 KB of its budget (measured: ~100 fit), and
  // this client's write would block if it filled.
  constexpr int events = static_cast<int>(ConnectionLink::inbox_limit) + 30;
  TestServer server;
  TestClient client(server.port());
  settle(client);
  client.send(key("block"));
  ASSERT_TRUE(TestServer::eventually([&] { return server.probe->blocked.load(); }));
  for (int seq = 1; seq <= events; ++seq) ASSERT_FALSE(client.send(move(seq))) << "seq " << seq;
  EXPECT_TRUE(server.log->wait_for({"connection #1", "reading paused"})) << server.log->all();
  server.probe->unblock.set_value();
  for (;;) {
    std::optional<ServerMessage> frame;
    ASSERT_NO_THROW(frame = client.receive()) << server.log->all();
    ASSERT_TRUE(frame);
    client.send(ack(frame->header["frame"].get<std::int64_t>()));
    if (frame->header["seq"] == events) break;
  }
  EXPECT_EQ(server.probe->inputs, events + 1);
}

// Two clients: #1 a bystander with a frame in hand, #2 the one under test.
struct TwoClients {
  explicit TwoClients(TestServer& server) {
    bystander = std::make_unique<TestClient>(server.port());
    bystander->send(resize(32, 32));
    frame_from(*bystander);  // connected (id 1) before the other connects
    other = std::make_unique<TestClient>(server.port());
    other->send(resize(40, 40));
    frame_from(*other);
  }
  std::unique_ptr<TestClient> bystander;
  std::unique_ptr<TestClient> other;
};

TEST(ServeServer, MalformedMessagesClose1008AndOthersGoOn) {
  TestServer server;
  TwoClients clients(server);
  clients.other->send_text("{not json");
  const std::optional<Closed> closed = clients.other->wait_closed();
  ASSERT_TRUE(closed);
  EXPECT_EQ(closed->code, 1008) << closed->error.message();
  EXPECT_TRUE(server.log->wait_for({"connection #2", "not valid JSON", "1008"}))
      << server.log->all();
  EXPECT_EQ(server.server->stats().protocol_errors, 1);
  expect_still_served(*clients.bystander, 1, 11);

  // Each kind of malformed message, each on its own connection.
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"[1,2]", "JSON object"},
      {R"({"type":"warp"})", "unknown"},
      {R"({"type":"resize","width":-3,"height":10})", "\"width\""},
      {R"({"type":"move","x":"1","y":2})", "\"x\""},
      {R"({"type":"button","x":1,"y":2,"button":0})", "\"down\""},
  };
  for (const auto& [text, says] : bad) {
    SCOPED_TRACE(text);
    TestClient client(server.port());
    client.send_text(text);
    const std::optional<Closed> c = client.wait_closed();
    ASSERT_TRUE(c);
    EXPECT_EQ(c->code, 1008);
    EXPECT_TRUE(server.log->wait_for({says, "1008"})) << server.log->all();
  }
  EXPECT_EQ(server.server->stats().protocol_errors, 1 + static_cast<long>(bad.size()));
  expect_still_served(*clients.bystander, 2, 12);
}

TEST(ServeServer, OversizedMessageCloses1009AndOthersGoOn) {
  TestServer server;
  TwoClients clients(server);
  // The server reads the whole message (discarding it) so that the page gets its close frame, not a reset.
  EXPECT_FALSE(clients.other->send_text(std::string(10 * 1024 * 1024, 'x')));
  const std::optional<Closed> closed = clients.other->wait_closed();
  ASSERT_TRUE(closed);
  EXPECT_EQ(closed->code, 1009) << closed->error.message();
  EXPECT_TRUE(server.log->wait_for({"connection #2", "larger than 65536"})) << server.log->all();
  EXPECT_EQ(server.server->stats().protocol_errors, 1);
  expect_still_served(*clients.bystander, 1, 21);
}

TEST(ServeServer, ClientVanishingMidStreamOnlyEndsItsConnection) {
  TestServer server({}, /*always_wants=*/true);
  TwoClients clients(server);
  // Let frames flow to the other client, then reset its socket with frames in flight.
  for (int i = 0; i < 5; ++i)
    clients.other->send(ack(frame_from(*clients.other).header["frame"].get<std::int64_t>()));
  clients.other->drop();
  EXPECT_TRUE(server.log->wait_for({"connection #2", "connection lost"})) << server.log->all();
  EXPECT_TRUE(TestServer::eventually([&] { return server.probe->destroyed == 1; }))
      << "the vanished client's session was not destroyed";
  EXPECT_EQ(server.server->stats().connections_open, 1);
  // The bystander's frames were never acked beyond the first: ack them all as they come.
  expect_still_served(*clients.bystander, 1, 31);
  EXPECT_FALSE(server.probe->wrong_thread);
}

TEST(ServeServer, PoliteCloseIsLoggedAndFreesTheSession) {
  TestServer server;
  TwoClients clients(server);
  clients.other->close();
  EXPECT_TRUE(server.log->wait_for({"connection #2", "closed by the page (1000)"}))
      << server.log->all();
  EXPECT_TRUE(TestServer::eventually([&] { return server.probe->destroyed == 1; }));
  expect_still_served(*clients.bystander, 1, 41);
}

TEST(ServeServer, FailingSessionCloses1011AndOthersGoOn) {
  TestServer server;
  TwoClients clients(server);
  clients.other->send(ack(1));
  clients.other->send(key("throw"));
  const std::optional<Closed> closed = clients.other->wait_closed();
  ASSERT_TRUE(closed);
  EXPECT_EQ(closed->code, 1011);
  EXPECT_TRUE(
      server.log->wait_for({"connection #2", "session failed", "fake session asked to fail"}))
      << server.log->all();
  expect_still_served(*clients.bystander, 1, 51);
}

TEST(ServeServer, ServesMaxClientsAtOnceAndRefusesOneMore) {
  constexpr int limit = 8;
  TestServer server([](ServerOptions& o) { o.max_clients = limit; });
  std::vector<std::unique_ptr<TestClient>> clients;
  for (int i = 0; i < limit; ++i) clients.push_back(std::make_unique<TestClient>(server.port()));
  for (int i = 0; i < limit; ++i) clients[i]->send(resize(32 + i, 20));
  for (int i = 0; i < limit; ++i) {
    const ServerMessage frame = frame_from(*clients[i]);
    EXPECT_EQ(frame.header["frame"], 1);
    EXPECT_EQ(frame.header["width"], 32 + i);
  }
  EXPECT_EQ(server.server->stats().connections_open, limit);

  const auto refused = refused_upgrade(server.port());
  EXPECT_EQ(refused.result(), http::status::service_unavailable);
  EXPECT_NE(refused.body().find("too many clients"), std::string::npos) << refused.body();
  EXPECT_TRUE(server.log->wait_for({"refused"})) << server.log->all();

  // A slot that frees is usable again.
  clients[0]->close();
  std::unique_ptr<TestClient> late;
  EXPECT_TRUE(TestServer::eventually([&] {
    try {
      late = std::make_unique<TestClient>(server.port());
      return true;
    } catch (const std::runtime_error&) {
      return false;
    }
  }));
  ASSERT_TRUE(late);
  late->send(resize(16, 16));
  EXPECT_EQ(frame_from(*late).header["frame"], 1);
  expect_still_served(*clients[limit - 1], 1, 61);
}

TEST(ServeServer, GetSlashServesThePage) {
  TestServer server;
  const auto response = http_get(server.port(), "/");
  EXPECT_EQ(response.result(), http::status::ok);
  EXPECT_EQ(response.body(), server.page_text);
  EXPECT_NE(std::string(response[http::field::content_type]).find("text/html"), std::string::npos);
  EXPECT_EQ(std::string(response[http::field::cache_control]), "no-store");
  EXPECT_EQ(http_get(server.port(), "/?reload=1").result(), http::status::ok);
}

TEST(ServeServer, OtherPathsAre404) {
  TestServer server;
  EXPECT_EQ(http_get(server.port(), "/nope").result(), http::status::not_found);
  EXPECT_EQ(http_get(server.port(), "/ws").result(),
            http::status::not_found);  // without an upgrade
}

TEST(ServeServer, StartOnABusyPortThrowsNamingIt) {
  TestServer first;
  const unsigned short port = first.port();
  ServerOptions options;
  options.bind = "127.0.0.1";
  options.port = port;
  Server second(options, {}, [] { return std::unique_ptr<Session>(); });
  try {
    second.start();
    FAIL() << "started on a port in use";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("127.0.0.1:" + std::to_string(port)), std::string::npos)
        << e.what();
  }
}

TEST(ServeServer, RenderThreadInitFailureIsStartsException) {
  ServerOptions options;
  options.port = 0;
  Server server(
      options, [] { throw std::runtime_error("no GL for you"); },
      [] { return std::unique_ptr<Session>(); });
  EXPECT_THROW(
      {
        try {
          server.start();
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "no GL for you");
          throw;
        }
      },
      std::runtime_error);
}

TEST(ServeServer, StopClosesConnections1001AndDestroysSessions) {
  TestServer server;
  TestClient client(server.port());
  client.send(resize(32, 32));
  frame_from(client);
  auto stopping = std::async(std::launch::async, [&] { server.server->stop(); });
  const std::optional<Closed> closed = client.wait_closed();
  ASSERT_TRUE(closed);
  EXPECT_EQ(closed->code, 1001);
  stopping.get();
  EXPECT_EQ(server.probe->destroyed, server.probe->created);
  EXPECT_EQ(server.server->stats().connections_open, 0);
  server.server->stop();  // idempotent
  server.server->wait();  // returns at once after stop
}

TEST(ServeServer, WaitReturnsAfterRequestStop) {
  TestServer server;
  auto waiting = std::async(std::launch::async, [&] { server.server->wait(); });
  EXPECT_EQ(waiting.wait_for(quiet_period), std::future_status::timeout)
      << "wait() returned before any stop";
  server.server->request_stop();
  EXPECT_EQ(waiting.wait_for(expect_within), std::future_status::ready);
}

TEST(ServeServer, AStopBySignalIsNotHeldUpByABusySession) {
  // A session stuck in its work: the render thread cannot see the stop until
  // it returns, so past the deadline the overdue action runs (by default it
  // ends the process; here it lets the session go, so the test can end).
  std::atomic<bool> overdue{false};
  std::shared_ptr<FakeProbe> probe;
  TestServer server([&](ServerOptions& o) {
    o.stop_deadline = 300ms;
    o.on_overdue_stop = [&] {
      overdue = true;
      probe->unblock.set_value();
    };
  });
  probe = server.probe;
  TestClient client(server.port());
  settle(client);
  client.send(key("block"));
  ASSERT_TRUE(TestServer::eventually([&] { return server.probe->blocked.load(); }));
  auto waiting = std::async(std::launch::async, [&] { server.server->wait(); });
  const auto asked = std::chrono::steady_clock::now();
  server.server->request_stop();
  ASSERT_EQ(waiting.wait_for(expect_within), std::future_status::ready) << server.log->all();
  EXPECT_TRUE(overdue) << server.log->all();
  EXPECT_GE(std::chrono::steady_clock::now() - asked, 300ms);
  EXPECT_TRUE(server.log->wait_for({"not stopped after 300 ms", "a session is still busy"}));
}

TEST(ServeServer, AStopBySignalInTimeRunsNoOverdueAction) {
  std::atomic<bool> overdue{false};
  TestServer server([&](ServerOptions& o) {
    o.stop_deadline = expect_within;  // the sanitizers slow a stop down too
    o.on_overdue_stop = [&] { overdue = true; };
  });
  TestClient client(server.port());
  settle(client);
  auto waiting = std::async(std::launch::async, [&] { server.server->wait(); });
  server.server->request_stop();
  ASSERT_EQ(waiting.wait_for(expect_within), std::future_status::ready);
  EXPECT_FALSE(overdue);
}

}  // namespace
}  // namespace epviz::serve::testing
