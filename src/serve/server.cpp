#include "serve/server.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>

#include "serve/http_session.hpp"
#include "serve/network_context.hpp"
#include "serve/render_loop.hpp"
#include "serve/shared_state.hpp"
#include "serve/websocket_connection.hpp"

// Two threads, each owning one kind of work:
// - the network thread runs an io_context: accepting, HTTP, WebSocket reads
//   and writes, all asynchronous, so one thread serves every connection and
//   the connection objects need no locks among themselves;
// - the render thread owns the GL context (render_thread_init) and therefore
//   every session; it renders and encodes, which is where the time goes.
// They meet only in shared_state.hpp: per connection an inbox, frame counters
// and a closed flag one way, posted messages to the connection's strand the
// other way.

namespace epviz::serve {

namespace net = boost::asio;
using tcp = net::ip::tcp;

namespace {

// How long stop() lets connections finish their close handshake before the
// io_context is stopped under them.
constexpr auto close_grace = std::chrono::seconds(1);

std::string address_text(const std::string& host, unsigned short port) {
  const bool ipv6 = host.find(':') != std::string::npos;
  return (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

}  // namespace

struct Server::Impl {
  Impl(ServerOptions opts, std::function<void()> init, SessionFactory factory)
      : options(std::move(opts)),
        render_thread_init(std::move(init)),
        make_session(std::move(factory)),
        log(options.log),
        network{options, log, counters, hub} {}

  void start();
  void stop();
  void accept_next();
  void begin_shutdown();  // network thread

  enum class State { created, running, stopped };

  ServerOptions options;
  std::function<void()> render_thread_init;
  SessionFactory make_session;
  ServerLog log;
  ServerCounters counters;
  RenderHub hub;
  NetworkContext network;
  // Optional so that stop() can destroy them (and with them every connection
  // still queued in the io_context) once the network thread has ended.
  std::optional<net::io_context> io;
  std::optional<tcp::acceptor> acceptor;
  std::optional<net::steady_timer> grace_timer;  // stop(): the close handshakes' deadline
  std::optional<net::steady_timer> retry_timer;  // accept after a failure
  std::thread network_thread;
  std::thread render_thread;
  unsigned short bound_port = 0;

  std::mutex
      lifecycle_mutex;  // start/stop; held through stop so a second caller waits for the first
  std::condition_variable stopped;
  State state = State::created;
  std::atomic<bool> stop_requested{false};
};

void Server::Impl::start() {
  std::lock_guard lock(lifecycle_mutex);
  if (state != State::created) throw std::logic_error("Server::start: already started");
  io.emplace(1);  // concurrency hint: one thread runs it
  const std::string where = address_text(options.bind, options.port);
  boost::system::error_code ec;
  tcp::resolver resolver(*io);
  const auto endpoints =
      resolver.resolve(options.bind, std::to_string(options.port),
                       tcp::resolver::passive | tcp::resolver::numeric_service, ec);
  if (ec || endpoints.empty())
    throw std::runtime_error("cannot listen on " + where + ": " +
                             (ec ? ec.message() : "no such address"));
  const tcp::endpoint endpoint = endpoints.begin()->endpoint();
  acceptor.emplace(*io);
  auto fail_if = [&](const char* step) {
    if (ec)
      throw std::runtime_error("cannot listen on " + where + ": " + step + ": " + ec.message());
  };
  acceptor->open(endpoint.protocol(), ec);
  fail_if("open");
  // Lets a restarted server take its port back from connections in
  // TIME_WAIT; on Linux it does not allow two listeners on one port.
  acceptor->set_option(net::socket_base::reuse_address(true), ec);
  fail_if("reuse_address");
  acceptor->bind(endpoint, ec);
  fail_if("bind");
  acceptor->listen(net::socket_base::max_listen_connections, ec);
  fail_if("listen");
  bound_port = acceptor->local_endpoint().port();
  network.origins.emplace(options.bind, bound_port, options.allowed_origins);

  // The render thread starts first and start() waits for its init, so a GL
  // context that cannot be created is start()'s exception, not a silent hang.
  std::promise<void> initialized;
  std::future<void> init_result = initialized.get_future();
  render_thread = std::thread([this, &initialized] {
    try {
      if (render_thread_init) render_thread_init();
    } catch (...) {
      initialized.set_exception(std::current_exception());
      return;
    }
    initialized.set_value();
    RenderLoop loop(options, hub, make_session, log, counters);
    loop.run();
  });
  try {
    init_result.get();
  } catch (...) {
    render_thread.join();
    acceptor.reset();
    io.reset();
    throw;
  }

  accept_next();
  network_thread = std::thread([this] {
    // A handler that throws (allocation failure, say) is logged and the loop
    // goes on: one bad connection must not take the others down.
    for (;;) {
      try {
        io->run();
        return;
      } catch (const std::exception& e) {
        log(std::string("network thread: ") + e.what());
      }
    }
  });
  state = State::running;
  log("serving on http://" + address_text(options.bind, bound_port) + "/");
}

void Server::Impl::accept_next() {
  acceptor->async_accept(net::make_strand(*io),
                         [this](boost::system::error_code ec, tcp::socket socket) {
                           if (ec == net::error::operation_aborted || !acceptor->is_open()) return;
                           if (!ec) {
                             std::make_shared<HttpSession>(std::move(socket), network)->start();
                             return accept_next();
                           }
                           // Out of file descriptors, typically: wait a little instead of spinning.
                           log(std::string("accept failed: ") + ec.message());
                           retry_timer.emplace(*io, std::chrono::milliseconds(100));
                           retry_timer->async_wait([this](boost::system::error_code wait_ec) {
                             if (!wait_ec && acceptor->is_open()) accept_next();
                           });
                         });
}

void Server::Impl::begin_shutdown() {
  network.stopping = true;
  boost::system::error_code ignored;
  acceptor->close(ignored);
  if (network.connections.empty()) return io->stop();
  network.on_all_closed = [this] { io->stop(); };
  // Copies: shutdown() may finish a connection at once, erasing it from the map.
  std::vector<std::shared_ptr<WebSocketConnection>> open;
  for (auto& [id, connection] : network.connections) open.push_back(connection);
  for (auto& connection : open) connection->shutdown();
  grace_timer.emplace(*io, close_grace);
  grace_timer->async_wait([this](boost::system::error_code ec) {
    if (!ec) io->stop();
  });
}

void Server::Impl::stop() {
  std::lock_guard lock(lifecycle_mutex);
  if (state == State::running) {
    // Sessions go first, on their own thread, while connections still stand.
    hub.request_stop();
    render_thread.join();
    net::post(*io, [this] { begin_shutdown(); });
    network_thread.join();
    network.on_all_closed = nullptr;  // connections destroyed below must not touch the io_context
    // Connections that did not finish in the grace period go now, while the
    // io_context their sockets belong to still exists. Moved out first: each
    // one's finish() erases itself from the map.
    auto unfinished = std::move(network.connections);
    network.connections.clear();
    unfinished.clear();
    grace_timer.reset();
    retry_timer.reset();
    acceptor.reset();
    io.reset();
  }
  state = State::stopped;
  stopped.notify_all();
}

Server::Server(ServerOptions options, std::function<void()> render_thread_init,
               SessionFactory make_session)
    : impl_(std::make_unique<Impl>(std::move(options), std::move(render_thread_init),
                                   std::move(make_session))) {}

Server::~Server() { stop(); }

void Server::start() { impl_->start(); }

unsigned short Server::port() const { return impl_->bound_port; }

void Server::stop() { impl_->stop(); }

void Server::request_stop() noexcept { impl_->stop_requested = true; }

void Server::wait() {
  std::unique_lock lock(impl_->lifecycle_mutex);
  while (impl_->state != Impl::State::stopped) {
    // Polled, not signalled: request_stop() runs in signal handlers, where
    // only the lock-free atomic store is allowed.
    impl_->stopped.wait_for(lock, std::chrono::milliseconds(100));
    if (impl_->stop_requested && impl_->state != Impl::State::stopped) {
      lock.unlock();
      stop_by_deadline();
      lock.lock();
    }
  }
}

void Server::stop_by_deadline() {
  const ServerOptions& o = impl_->options;
  std::promise<void> stopped;
  std::future<void> done = stopped.get_future();
  // A watchdog, since nothing can interrupt a session in the middle of its
  // render: the render thread finishes its frame before it sees the stop.
  std::thread watchdog([&o, &done, &log = impl_->log] {
    if (done.wait_for(o.stop_deadline) != std::future_status::timeout) return;
    log("not stopped after " + std::to_string(o.stop_deadline.count()) +
        " ms (a session is still busy): exiting without waiting for it");
    if (o.on_overdue_stop) return o.on_overdue_stop();
    std::fflush(nullptr);
    std::_Exit(0);
  });
  stop();
  stopped.set_value();
  watchdog.join();
}

ServerStats Server::stats() const {
  const ServerCounters& c = impl_->counters;
  ServerStats s;
  s.connections_accepted = c.connections_accepted;
  s.connections_open = c.connections_open;
  s.frames_sent = c.frames_sent;
  s.protocol_errors = c.protocol_errors;
  s.outbox_bytes = c.outbox_bytes;
  s.outbox_bytes_peak = c.outbox_bytes_peak;
  s.outbox_overflows = c.outbox_overflows;
  s.downscaled_frames = c.downscaled_frames;
  return s;
}

}  // namespace epviz::serve
