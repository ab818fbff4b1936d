#pragma once
// The frame server behind `epviz serve`: HTTP for the page, a WebSocket per
// browser tab for events in and frames out (Boost.Beast). Protocol:
// docs/serve.md. Knows nothing of physics or GL: sessions come from a factory
// and are driven on one render thread.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "serve/session.hpp"

namespace epviz::serve {

enum class ImageFormat { jpeg, png };

struct ServerOptions {
  std::string bind = "127.0.0.1";
  unsigned short port = 8080;                 // 0: any free port (see Server::port())
  std::filesystem::path page;                 // the HTML file served at "/"
  std::size_t max_message_bytes = 64 * 1024;  // larger client messages close that connection
  int max_frames_in_flight = 2;             // frames sent but not yet acknowledged, per connection
  int max_clients = 16;                     // further connections are refused with a reason
  int max_width = 3840, max_height = 2160;  // resize requests are clamped to these
  ImageFormat image_format = ImageFormat::jpeg;
  int jpeg_quality = 85;
  // One line per event worth logging (connections, closes and their reasons).
  std::function<void(const std::string&)> log;
  // Records the first connection's messages here, one JSON line each as the
  // page sent them, with {"type":"render"} where a frame was rendered: the
  // session calls in order, which live::replay() repeats without a browser.
  std::filesystem::path record_path;
};

struct ServerStats {
  long connections_accepted = 0;
  long connections_open = 0;
  long frames_sent = 0;
  long protocol_errors = 0;  // connections closed for malformed or oversized messages
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
  // ~100 ms, calls stop() and returns.
  void request_stop() noexcept;
  ServerStats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace epviz::serve
