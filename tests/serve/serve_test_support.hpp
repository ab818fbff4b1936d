#pragma once
// Test doubles for the frame server: a fake Session that paints a solid
// colour (a new one per input event) and reports what was done to it, a
// WebSocket client whose every wait has a deadline, and a server fixture
// that captures the log. Boost.Beast stays in serve_test_support.cpp (the
// client's connection) and in http_test_support.hpp (plain HTTP requests),
// which only the tests that make such requests include.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <boost/system/error_code.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "serve/protocol.hpp"
#include "serve/server.hpp"
#include "serve/session.hpp"
#include "support/temp_dir.hpp"

namespace epviz::serve::testing {

using namespace std::chrono_literals;

// How many times slower than the optimised build the server runs here: 1,
// or EPVIZ_TEST_SLOWDOWN (the ThreadSanitizer pass sets it). Tests that give
// the server a wall-clock time to do something multiply it by this.
int slowdown();

// Long enough for a loaded two-core machine; a passing run never waits this long.
inline const std::chrono::milliseconds expect_within = 10s * slowdown();
// How long "nothing arrives" is watched for.
inline constexpr auto quiet_period = 300ms;

// What a fake session reports as its render stages when FakeProbe::reports_stages.
inline constexpr RenderStages fake_stages{0.5, 2.0, 0.25};

// The fake session's colour after `inputs` input events.
glm::u8vec4 fake_colour(int inputs);

// What the fake sessions report, shared with the test thread.
struct FakeProbe {
  std::atomic<int> created{0};
  std::atomic<int> destroyed{0};
  std::atomic<int> renders{0};
  std::atomic<int> large_renders{0};  // of a megapixel or more
  std::atomic<int> inputs{0};
  std::atomic<bool> wrong_thread{false};  // a session was touched off the render thread
  std::atomic<std::thread::id> render_thread{};
  // Simulated render cost: render() sleeps this long per million pixels
  // (sleeping, not spinning, so the cost does not depend on the machine's load).
  std::atomic<int> render_ms_per_megapixel{0};
  // Whether the fake sessions report their render stages (fake_stages) or,
  // like a session that does not measure them, none.
  std::atomic<bool> reports_stages{false};
  // The last pointer position a session got, and the last view scale it was told.
  std::atomic<float> last_x{-1.0f}, last_y{-1.0f};
  std::atomic<double> view_scale{1.0};
  // A key event "block" holds the render thread in input() until this is set.
  std::atomic<bool> blocked{false};  // a session is waiting in input("block")
  std::promise<void> unblock;
  std::shared_future<void> unblocked = unblock.get_future().share();
  void check_thread() {
    if (std::this_thread::get_id() != render_thread.load()) wrong_thread = true;
  }
};

// Paints fake_colour(inputs seen). Wants a frame after a resize or input, or
// always. A key event "notice" / "download" queues one; "throw" makes the
// next render() throw; "block" waits for FakeProbe::unblock. Its controls:
// one rectangle, "play", the size of the frame.
class FakeSession : public Session {
 public:
  FakeSession(std::shared_ptr<FakeProbe> probe, bool always_wants);
  ~FakeSession() override;
  void resize(int width, int height) override;
  void input(const render::InputEvent& event) override;
  bool wants_frame() const override;
  const render::RgbaImage& render() override;
  std::vector<Download> take_downloads() override;
  std::vector<std::string> take_notices() override;
  std::string controls_json() const override;
  RenderStages last_render_stages() const override;
  void set_view_scale(double scale) override;

 private:
  std::shared_ptr<FakeProbe> probe_;
  bool always_wants_;
  bool dirty_ = true;
  bool throw_next_ = false;
  int inputs_ = 0;
  render::RgbaImage image_;
  std::vector<Download> downloads_;
  std::vector<std::string> notices_;
};

// Lines from ServerOptions::log, waitable.
class LogCapture {
 public:
  void add(const std::string& line);
  // Whether a line containing every one of `parts` arrives within `timeout`.
  bool wait_for(const std::vector<std::string>& parts,
                std::chrono::milliseconds timeout = expect_within);
  std::string all() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable added_;
  std::vector<std::string> lines_;
};

// A started server with fake sessions on a free port and a page file.
struct TestServer {
  explicit TestServer(const std::function<void(ServerOptions&)>& configure = {},
                      bool always_wants = false);
  ~TestServer();
  unsigned short port() const { return server->port(); }
  // Polls `condition` until it holds or `timeout` passes (for state with no event to wait on).
  static bool eventually(const std::function<bool()>& condition,
                         std::chrono::milliseconds timeout = expect_within);

  std::shared_ptr<FakeProbe> probe = std::make_shared<FakeProbe>();
  std::shared_ptr<LogCapture> log = std::make_shared<LogCapture>();
  test::TempDir page_dir;
  std::filesystem::path page;
  std::string page_text;
  std::unique_ptr<Server> server;
};

// How the server ended a connection, as the client saw it.
struct Closed {
  boost::system::error_code error;  // websocket::error::closed after a close frame
  int code = -1;                    // the close frame's code, -1 without one
};

// A WebSocket client on its own io_context; every wait has a deadline. A
// receive() that times out leaves its read pending for the next call, so no
// message is lost and nothing is cancelled.
class TestClient {
 public:
  // Connects and upgrades; throws std::runtime_error when either fails.
  explicit TestClient(unsigned short port);
  ~TestClient();

  boost::system::error_code send_text(const std::string& text);
  boost::system::error_code send(const nlohmann::json& message) {
    return send_text(message.dump());
  }
  // The next server message, or nullopt when none arrives within `timeout`.
  // Throws std::runtime_error if the connection ends.
  std::optional<ServerMessage> receive(std::chrono::milliseconds timeout = expect_within);
  // Skips messages until the connection ends; nullopt when it does not within `timeout`.
  std::optional<Closed> wait_closed(std::chrono::milliseconds timeout = expect_within);
  void close();  // polite WebSocket close (code 1000)
  void drop();   // resets the TCP connection without any WebSocket close

 private:
  struct Connection;  // the io_context, the WebSocket stream and its buffer (Beast)
  void start_read();
  bool run_until(const bool& done, std::chrono::milliseconds timeout);

  std::unique_ptr<Connection> c_;
  bool read_pending_ = false;
  bool read_done_ = false;
  boost::system::error_code read_error_;
};

// What a page sends.
inline nlohmann::json resize(int width, int height) {
  return {{"type", "resize"}, {"width", width}, {"height", height}};
}
inline nlohmann::json ack(std::int64_t frame) { return {{"type", "ack"}, {"frame", frame}}; }

// A page that asks for a size, then reads and acks every frame on a thread of
// its own, noting when each came and its size, until it is destroyed or the
// connection ends.
class ReadingPage {
 public:
  ReadingPage(unsigned short port, int width, int height);
  ~ReadingPage();
  std::vector<std::chrono::steady_clock::time_point> arrivals() const;
  int frames() const { return int(arrivals().size()); }
  std::pair<int, int> last_size() const;

 private:
  void run();
  TestClient client_;
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::vector<std::chrono::steady_clock::time_point> arrivals_;
  std::pair<int, int> last_size_{0, 0};
  std::thread thread_;
};

// Decodes a JPEG frame payload to RGBA (TurboJPEG); throws on failure.
render::RgbaImage decode_jpeg(const std::vector<std::uint8_t>& jpeg);

}  // namespace epviz::serve::testing
