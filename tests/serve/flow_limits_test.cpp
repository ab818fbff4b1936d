// A page that acknowledges frames it never read, or does not read at all,
// cannot make the server queue frames without bound: a frame counts as
// delivered only once written, the outbox is bounded in bytes, and a
// connection that stays over the bound is dropped while others go on.
#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include "serve_test_support.hpp"

namespace epviz::serve::testing {
namespace {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using nlohmann::json;

// Sends, never reads; a tiny receive buffer makes the server's writes stall soon.
class NonReadingClient {
 public:
  explicit NonReadingClient(unsigned short port) : ws_(io_) {
    tcp::socket& socket = beast::get_lowest_layer(ws_).socket();
    socket.open(tcp::v4());
    socket.set_option(net::socket_base::receive_buffer_size(4096));
    socket.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port));
    ws_.handshake("127.0.0.1:" + std::to_string(port), "/ws");
    ws_.text(true);
  }
  // Errors are ignored: the server may drop this client, which is the point.
  void send(const json& message) {
    beast::error_code ignored;
    ws_.write(net::buffer(message.dump()), ignored);
  }

 private:
  net::io_context io_;
  websocket::stream<beast::tcp_stream> ws_;
};

TEST(ServeFlowLimits, ForgedAcksDoNotGrowTheOutbox) {
  TestServer server({}, /*always_wants=*/true);
  // The size of one full-size frame, as a reading page receives it.
  std::size_t frame_bytes = 0;
  {
    TestClient reference(server.port());
    reference.send(resize(3840, 2160));
    const std::optional<ServerMessage> frame = reference.receive();
    ASSERT_TRUE(frame);
    frame_bytes = frame->payload.size();
  }
  ASSERT_GT(frame_bytes, 4096u);
  // The reference page's session is gone, so every large frame from here on
  // is the forger's.
  ASSERT_TRUE(TestServer::eventually([&] { return server.probe->destroyed == 1; }));

  ReadingPage bystander(server.port(), 64, 64);
  NonReadingClient forger(server.port());
  // Counted before the forger's resize, so that its first frames are counted
  // too: a frame drawn before this count would hold its acks two behind, the
  // window shut.
  const int renders_before = server.probe->large_renders;
  forger.send(resize(3840, 2160));
  // Acks each frame once it has been rendered (one behind, so never one
  // not yet sent), reading none: before writes counted, this kept the
  // window open and every frame went into the outbox.
  // For 3 s, and on until the forger has had enough frames rendered to show
  // anything (a loaded machine renders few 4K frames a second), up to 60 s.
  const auto start = std::chrono::steady_clock::now();
  const auto enough = [&] {
    return server.probe->large_renders - renders_before > 3 * ServerOptions{}.max_frames_in_flight;
  };
  std::int64_t acked = 0;
  for (;;) {
    const auto waited = std::chrono::steady_clock::now() - start;
    if ((waited >= 3s * slowdown() && enough()) || waited >= 60s * slowdown()) break;
    const std::int64_t rendered = server.probe->large_renders - renders_before;
    if (rendered - 1 > acked) forger.send(ack(acked = rendered - 1));
    std::this_thread::sleep_for(2ms);
  }
  const ServerStats stats = server.server->stats();
  // Counts, not rates: how many frames fit in the window depends on the
  // machine and the build (a third as many under ASan). Round-robin gives the
  // reading page one frame per round, as many as the forger's renders.
  const int forger_renders = server.probe->large_renders - renders_before;
  EXPECT_GT(forger_renders, 3 * ServerOptions{}.max_frames_in_flight)
      << "the forged acks never opened the forger's window: the test shows nothing";
  EXPECT_LE(stats.outbox_bytes_peak, long(4 * frame_bytes + 64 * 1024))
      << "frames piled up for a page that reads none (frame " << frame_bytes << " bytes)";
  EXPECT_GE(bystander.frames(), forger_renders / 2)
      << "the reading page lost its share of the rounds (forger rendered " << forger_renders << ")";
  EXPECT_EQ(stats.protocol_errors, 0) << server.log->all();
}

TEST(ServeFlowLimits, APageThatDoesNotReadIsDroppedOthersGoOn) {
  TestServer server(
      [](ServerOptions& o) {
        o.max_outbox_bytes = 16 * 1024;
        o.outbox_grace = 300ms;
        // No acknowledgement window: frames go out as fast as they are drawn,
        // so a page that reads nothing fills its socket's buffers and then the
        // outbox. (With the window, the test would have to acknowledge exactly
        // the frames sent to a page that reads none of them: those drawn
        // before its resize arrived are not known to it.)
        o.max_frames_in_flight = 1 << 30;
      },
      /*always_wants=*/true);
  ReadingPage bystander(server.port(), 64, 64);
  NonReadingClient stuck(server.port());
  stuck.send(resize(3840, 2160));
  // The kernel's send buffer for the connection grows to as much as 4 MB
  // (tcp_wmem) before the outbox holds a byte: tens of 4K frames, which under
  // ASan take over 10 s to draw and encode. Up to 60 s, then.
  EXPECT_TRUE(TestServer::eventually([&] { return server.server->stats().outbox_overflows > 0; },
                                     60s * slowdown()));
  EXPECT_TRUE(server.log->wait_for({"connection #2", "the page does not read; dropped"}))
      << server.log->all();
  EXPECT_EQ(server.server->stats().outbox_overflows, 1);
  EXPECT_TRUE(TestServer::eventually([&] { return server.probe->destroyed == 1; }))
      << "the dropped page's session lives on";
  EXPECT_TRUE(TestServer::eventually([&] {
    return server.server->stats().outbox_bytes < 64 * 1024;
  })) << "the dropped outbox is still counted";
  const int before = bystander.frames();
  EXPECT_TRUE(TestServer::eventually([&] { return bystander.frames() >= before + 10; }))
      << "the reading page stopped getting frames";
}

}  // namespace
}  // namespace epviz::serve::testing
