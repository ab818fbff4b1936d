#pragma once
// The frame server behind `epviz serve`: HTTP for the page, a WebSocket per
// browser tab for events in and frames out (Boost.Beast). Protocol:
// docs/serve.md. Knows nothing of physics or GL: sessions come from a factory
// and are driven on one render thread.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "serve/session.hpp"

namespace epviz::serve {

enum class ImageFormat { jpeg, png };

struct ServerOptions {
  std::string bind = "127.0.0.1";
  unsigned short port = 8080;  // 0: any free port (see Server::port())
  std::filesystem::path page;  // the HTML file served at "/"
  // Origins besides the server's own whose pages may open the WebSocket
  // ("http://host:port"); see OriginPolicy. Requests whose Host does not
  // name this server get 403 whatever their origin.
  std::vector<std::string> allowed_origins;
  std::size_t max_message_bytes = 64 * 1024;  // larger client messages close that connection
  int max_frames_in_flight = 2;  // frames sent but not yet acknowledged, per connection
  // Bytes waiting to be written to one connection; a connection that stays
  // above this for outbox_grace (a page that does not read) is dropped.
  std::size_t max_outbox_bytes = 32u * 1024 * 1024;
  std::chrono::milliseconds outbox_grace{10000};
  int max_clients = 16;                     // further connections are refused with a reason
  int max_width = 3840, max_height = 2160;  // resize requests are clamped to these
  // Pixels rendered in one round over all connections (each gets at most one
  // frame a round): when the views together are larger, all are rendered
  // smaller by one factor, so no connection waits long for its frame. The
  // default is two 3840x2160 views; 0: no budget.
  long pixel_budget = 2L * 3840 * 2160;
  // Adaptive resolution: while a connection's frames take longer than this
  // (the average of the last few; a frame's cost is the longer of the
  // server's render + encode and the page's decoding, which it reports with
  // its ack), its view is rendered
  // smaller, down to min_detail of each side (the page stretches it), and
  // larger again when they get cheap; when the picture rests (the session
  // wants no frame) it is rendered once more at full size, as map viewers
  // sharpen a map. 0: off (always full size within the pixel budget).
  double frame_budget_ms = 0.0;
  double min_detail = 0.5;
  // How long the picture must have rested before it is sharpened: a pointer
  // that pauses between moves does not pay for a full-size frame each time.
  std::chrono::milliseconds rest_before_sharpening{250};
  ImageFormat image_format = ImageFormat::jpeg;
  int jpeg_quality = 85;
  // One line per event worth logging (connections, closes and their reasons).
  std::function<void(const std::string&)> log;
  // How long a stop asked for by a signal (request_stop) may take. Past it
  // (a session busy in a frame that has not ended, a connection that does
  // not close) `on_overdue_stop` runs, which by default ends the process at
  // once with status 0, as a stop does: a signal to stop is not a request to
  // wait for the work in hand.
  std::chrono::milliseconds stop_deadline{1500};
  std::function<void()> on_overdue_stop;
  // Records the first connection's messages here, one JSON line each as the
  // page sent them, with {"type":"render"} where a frame was rendered: the
  // session calls in order, which live::replay() repeats without a browser.
  std::filesystem::path record_path;
};

struct ServerStats {
  long connections_accepted = 0;
  long connections_open = 0;
  long frames_sent = 0;
  long protocol_errors = 0;    // connections closed for malformed or oversized messages
  long outbox_bytes = 0;       // waiting to be written now, all connections together
  long outbox_bytes_peak = 0;  // the most that ever waited
  long outbox_overflows = 0;   // connections dropped for not reading
  long downscaled_frames = 0;  // frames rendered smaller than asked (pixel budget, frame budget)
};

class Server {
 public:
  // `render_thread_init` runs first on the render thread (create the GL
  // context there); `make_session` then runs there for each connection.
  Server(ServerOptions options, std::function<void()> render_thread_init,
         SessionFactory make_session);
  ~Server();  // stops
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Binds and starts the network and render threads. Throws std::runtime_error
  // naming the address when it cannot bind.
  void start();
  unsigned short port() const;  // the bound port, after start()
  // Closes every connection and joins the threads; safe to call twice.
  void stop();
  // Blocks until stop() is called from another thread or a signal handler.
  void wait();
  // Async-signal-safe (one lock-free atomic store), for SIGINT/SIGTERM
  // handlers, where stop() itself must not run: wait() notices within
  // ~100 ms, calls stop() and returns, or past ServerOptions::stop_deadline
  // runs on_overdue_stop.
  void request_stop() noexcept;
  ServerStats stats() const;

 private:
  void stop_by_deadline();  // stop(), or on_overdue_stop past the deadline

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace epviz::serve
