#pragma once
// One browser tab's WebSocket on the network thread: reads page messages
// into its ConnectionLink (acks are recorded at once), writes the render
// thread's messages one at a time (Beast allows a single write in flight, so
// they wait in an outbox, bounded in bytes), and closes with the protocol's
// codes.
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "serve/network_context.hpp"
#include "serve/shared_state.hpp"

namespace epviz::serve {

// "ADDRESS:PORT" of the client at the other end, for the log.
std::string peer_of(boost::beast::tcp_stream& stream);

class WebSocketConnection : public ConnectionOutlet,
                            public std::enable_shared_from_this<WebSocketConnection> {
 public:
  // `context.websocket_clients` already counts this connection; finishing releases it.
  WebSocketConnection(boost::beast::tcp_stream stream, NetworkContext& context, long id);
  ~WebSocketConnection() override;

  // Network thread: answers the upgrade request, then serves.
  void start(boost::beast::http::request<boost::beast::http::string_body> request);

  // Network thread, when the server stops: a polite close (1001) once
  // upgraded, an abrupt one during the handshake.
  void shutdown();

  // ConnectionOutlet: any thread; each hops onto this connection's strand.
  void send(std::vector<std::uint8_t> message, std::int64_t frame) override;
  void resume_reading() override;
  void close(std::uint16_t code, std::string reason) override;

 private:
  void on_accept(boost::beast::error_code ec);
  void read_next();
  void on_read(boost::beast::error_code ec);
  void handle_text(std::string_view text);
  void protocol_error(const std::string& problem);
  void write_next();
  void watch_outbox();  // arms or disarms the overflow deadline after the outbox changed
  void release_outbox_bytes(std::size_t bytes);
  void start_close(std::uint16_t code, std::string reason);
  // The one exit: marks the link closed, frees the client slot, logs `why`
  // (when not empty). Later errors from the same connection are ignored.
  void finish(const std::string& why);

  // No permessage-deflate: the server never offers it, and without it Beast
  // leaves its zlib code out of the stream (10 % of this file's compile time).
  boost::beast::websocket::stream<boost::beast::tcp_stream, false> ws_;
  NetworkContext& context_;
  const long id_;
  std::string peer_;  // the client's address, for the log
  // Kept until the handshake completes rather than trusting Beast to copy it.
  boost::beast::http::request<boost::beast::http::string_body> upgrade_request_;
  std::shared_ptr<ConnectionLink> link_;  // from a successful upgrade on
  boost::beast::flat_buffer buffer_;
  struct Outgoing {
    std::vector<std::uint8_t> bytes;
    std::int64_t frame = 0;                             // 0: not a frame
    std::chrono::steady_clock::time_point handed_over;  // when the render thread sent it
  };
  std::deque<Outgoing> outbox_;                // front() is being written while writing_
  void note_written(const Outgoing& written);  // a frame's queue and send times
  std::size_t outbox_bytes_ = 0;
  boost::asio::steady_timer overflow_timer_;
  bool overflow_armed_ = false;
  bool writing_ = false;
  std::chrono::steady_clock::time_point write_started_;  // of outbox_.front(), while writing_
  bool reading_ = false;
  bool read_paused_ = false;  // the link's inbox is full
  bool closing_ = false;      // we sent (or are sending) a close frame
  bool finished_ = false;
};

}  // namespace epviz::serve
