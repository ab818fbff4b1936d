#include "serve/websocket_connection.hpp"

#include <chrono>

#include <boost/asio/post.hpp>

namespace epviz::serve {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;

namespace {

// A close frame's reason is at most 123 bytes (RFC 6455, 5.5), and browsers
// fail the connection on invalid UTF-8 in it, so cut at a character boundary.
std::string close_reason_text(std::string text) {
  constexpr std::size_t limit = 123;
  if (text.size() <= limit) return text;
  std::size_t end = limit;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  text.resize(end);
  return text;
}

}  // namespace

std::string peer_of(beast::tcp_stream& stream) {
  beast::error_code ec;
  const auto endpoint = stream.socket().remote_endpoint(ec);
  if (ec) return "an unknown address";
  return endpoint.address().to_string() + ":" + std::to_string(endpoint.port());
}

WebSocketConnection::WebSocketConnection(beast::tcp_stream stream, NetworkContext& context, long id)
    : ws_(std::move(stream)),
      context_(context),
      id_(id),
      peer_(peer_of(beast::get_lowest_layer(ws_))),
      overflow_timer_(ws_.get_executor()) {}

WebSocketConnection::~WebSocketConnection() {
  // Only reached without finish() when Server::stop ends the connections
  // that its grace period did not see closed.
  finish("");
}

void WebSocketConnection::start(http::request<http::string_body> request) {
  upgrade_request_ = std::move(request);
  // Beast's WebSocket timeouts replace the TCP stream's: a handshake or close
  // that stalls, or a page silent through a keep-alive ping, ends the connection
  // (a tab whose machine vanished would otherwise hold a client slot forever).
  beast::get_lowest_layer(ws_).expires_never();
  websocket::stream_base::timeout timeouts{};
  timeouts.handshake_timeout = std::chrono::seconds(10);
  timeouts.idle_timeout = std::chrono::seconds(60);
  timeouts.keep_alive_pings = true;
  ws_.set_option(timeouts);
  ws_.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& response) { response.set(http::field::server, "epviz"); }));
  // max_message_bytes is enforced in read_next/on_read, not with Beast's
  // read_message_max: on an oversized message Boost 1.74's Beast sends the
  // 1009 close frame and then, in its teardown, reads at most 2 KiB before
  // closing the socket, so a page still sending gets a TCP reset and never
  // sees the 1009 (observed: the client's write fails with EPIPE and it reads
  // no close code). Our own check closes with async_close, which reads and
  // discards the rest of the message until the page's close reply.
  ws_.read_message_max(0);  // 0: Beast's own limit off
  // One WebSocket frame per message: a frame for the page is written in one
  // go instead of in write-buffer-sized pieces.
  ws_.auto_fragment(false);
  ws_.async_accept(upgrade_request_,
                   beast::bind_front_handler(&WebSocketConnection::on_accept, shared_from_this()));
}

void WebSocketConnection::on_accept(beast::error_code ec) {
  upgrade_request_ = {};
  if (finished_) return;
  if (ec) {
    finish("WebSocket handshake with " + peer_ + " failed: " + ec.message());
    return;
  }
  link_ = std::make_shared<ConnectionLink>(id_, std::weak_ptr<ConnectionOutlet>(weak_from_this()));
  ++context_.counters.connections_open;
  context_.log(connection_name(id_) + ": opened from " + peer_);
  context_.hub.add(link_);
  read_next();
}

void WebSocketConnection::shutdown() {
  if (link_) {
    start_close(close_going_away, "server stopping");
  } else {
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().close(ignored);
  }
}

void WebSocketConnection::read_next() {
  if (reading_ || read_paused_ || closing_ || finished_) return;
  reading_ = true;
  // Never more than one byte past the limit: that byte is how we know.
  const std::size_t limit = context_.options.max_message_bytes + 1 - buffer_.size();
  ws_.async_read_some(
      buffer_, limit,
      [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
}

void WebSocketConnection::on_read(beast::error_code ec) {
  reading_ = false;
  if (finished_) return;
  if (ec == websocket::error::closed) {
    finish("closed by the page (" + std::to_string(static_cast<int>(ws_.reason().code)) + ")");
  } else if (ec == net::error::operation_aborted) {
    finish("");  // we closed the socket ourselves
  } else if (ec &&
             ec.category() == websocket::make_error_code(websocket::error::closed).category()) {
    // Beast failed the connection itself (invalid UTF-8 in a text message, a bad frame).
    ++context_.counters.protocol_errors;
    finish("WebSocket protocol violation: " + ec.message());
  } else if (ec) {
    finish("connection lost: " + ec.message());
  } else if (buffer_.size() > context_.options.max_message_bytes) {
    buffer_.clear();
    ++context_.counters.protocol_errors;
    const std::string problem =
        "message larger than " + std::to_string(context_.options.max_message_bytes) + " bytes";
    context_.log(connection_name(id_) + ": " + problem + "; closing (1009)");
    start_close(close_too_big, problem);  // Beast's close drains the rest of the message
  } else if (!ws_.is_message_done()) {
    read_next();  // more of the same message
  } else if (!ws_.got_text()) {
    buffer_.clear();
    protocol_error("binary message (the page sends JSON text)");
  } else {
    const auto data = buffer_.data();
    handle_text(std::string_view(static_cast<const char*>(data.data()), data.size()));
    buffer_.clear();
    read_next();
  }
}

void WebSocketConnection::handle_text(std::string_view text) {
  ClientMessage message;
  try {
    message = parse_client_message(text);
  } catch (const ProtocolError& e) {
    protocol_error(e.what());
    return;
  }
  if (const Ack* ack = std::get_if<Ack>(&message)) {
    // Acks skip the inbox: they only move the flow-control window, and the
    // render thread may be asleep waiting for exactly this.
    if (!link_->acknowledge(ack->frame)) {
      protocol_error("ack for frame " + std::to_string(ack->frame) + ", but only " +
                     std::to_string(link_->frames_sent.load()) + " frames were sent");
      return;
    }
    if (ack->decode_ms >= 0) link_->note_decoded({ack->frame, ack->decode_ms});
  } else if (!link_->push(std::move(message))) {
    // Worth a line: it means the session is slow or stuck in the render thread.
    read_paused_ = true;
    context_.log(connection_name(id_) + ": " + std::to_string(ConnectionLink::inbox_limit) +
                 " messages wait for the render thread; reading paused");
  }
  context_.hub.notify();
}

void WebSocketConnection::protocol_error(const std::string& problem) {
  ++context_.counters.protocol_errors;
  context_.log(connection_name(id_) + ": " + problem + "; closing (1008)");
  start_close(close_policy_error, problem);
}

void WebSocketConnection::send(std::vector<std::uint8_t> message, std::int64_t frame) {
  const auto handed_over = std::chrono::steady_clock::now();  // the queue stage starts here
  net::post(ws_.get_executor(), [self = shared_from_this(), message = std::move(message), frame,
                                 handed_over]() mutable {
    if (self->closing_ || self->finished_) return;
    self->outbox_bytes_ += message.size();
    const long total = self->context_.counters.outbox_bytes += long(message.size());
    long peak = self->context_.counters.outbox_bytes_peak;
    while (total > peak &&
           !self->context_.counters.outbox_bytes_peak.compare_exchange_weak(peak, total)) {
    }
    self->outbox_.push_back({std::move(message), frame, handed_over});
    self->watch_outbox();
    self->write_next();
  });
}

void WebSocketConnection::release_outbox_bytes(std::size_t bytes) {
  outbox_bytes_ -= bytes;
  context_.counters.outbox_bytes -= long(bytes);
}

void WebSocketConnection::watch_outbox() {
  const std::size_t limit = context_.options.max_outbox_bytes;
  if (outbox_bytes_ <= limit) {
    if (overflow_armed_) overflow_timer_.cancel();
    overflow_armed_ = false;
    return;
  }
  if (overflow_armed_) return;
  overflow_armed_ = true;
  overflow_timer_.expires_after(context_.options.outbox_grace);
  overflow_timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
    if (ec || self->finished_ || !self->overflow_armed_) return;
    self->overflow_armed_ = false;
    if (self->outbox_bytes_ <= self->context_.options.max_outbox_bytes) return;
    ++self->context_.counters.outbox_overflows;
    // No close frame: it would wait behind the writes that do not complete.
    self->finish(std::to_string(self->outbox_bytes_) + " bytes waited to be written for " +
                 std::to_string(self->context_.options.outbox_grace.count()) + " ms (more than " +
                 std::to_string(self->context_.options.max_outbox_bytes) +
                 "): the page does not read; dropped");
  });
}

void WebSocketConnection::resume_reading() {
  net::post(ws_.get_executor(), [self = shared_from_this()] {
    self->read_paused_ = false;
    self->read_next();
  });
}

void WebSocketConnection::close(std::uint16_t code, std::string reason) {
  net::post(ws_.get_executor(),
            [self = shared_from_this(), code, reason = std::move(reason)]() mutable {
              self->start_close(code, std::move(reason));
            });
}

void WebSocketConnection::write_next() {
  if (writing_ || outbox_.empty() || closing_ || finished_) return;
  writing_ = true;
  write_started_ = std::chrono::steady_clock::now();
  ws_.binary(true);
  ws_.async_write(net::buffer(outbox_.front().bytes),
                  [self = shared_from_this()](beast::error_code ec, std::size_t) {
                    self->writing_ = false;
                    const Outgoing written = std::move(self->outbox_.front());
                    self->outbox_.pop_front();
                    if (self->finished_) return;  // finish() released the outbox
                    self->release_outbox_bytes(written.bytes.size());
                    self->watch_outbox();
                    if (!ec && written.frame > 0) {
                      self->note_written(written);
                      // Only now may an ack of this frame open the window.
                      self->link_->frames_written = written.frame;
                      self->context_.hub.notify();
                    }
                    if (ec) {
                      self->finish(ec == net::error::operation_aborted
                                       ? ""
                                       : "connection lost while writing: " + ec.message());
                      return;
                    }
                    self->write_next();
                  });
}

void WebSocketConnection::note_written(const Outgoing& written) {
  using ms = std::chrono::duration<double, std::milli>;
  const ConnectionLink::WriteTiming timing{
      written.frame, ms(write_started_ - written.handed_over).count(),
      ms(std::chrono::steady_clock::now() - write_started_).count()};
  context_.counters.stages.record(Stage::queue, timing.queue_ms);
  context_.counters.stages.record(Stage::send, timing.send_ms);
  link_->note_written(timing);
}

void WebSocketConnection::start_close(std::uint16_t code, std::string reason) {
  if (closing_ || finished_ || !link_) return;
  closing_ = true;
  ws_.async_close(websocket::close_reason(static_cast<websocket::close_code>(code),
                                          close_reason_text(std::move(reason))),
                  [self = shared_from_this()](beast::error_code) { self->finish(""); });
}

void WebSocketConnection::finish(const std::string& why) {
  if (finished_) return;
  finished_ = true;
  // Erasing from context_.connections may drop the last owner; stay alive
  // to the end of this function (null in the destructor, which needs none).
  const auto keep_alive = weak_from_this().lock();
  if (!why.empty()) context_.log(connection_name(id_) + ": " + why);
  // Counters first: once the link says closed, the render thread may drop
  // the session, and whoever watches both must not see the session gone
  // while the connection still counts as open.
  if (link_) --context_.counters.connections_open;
  release_outbox_bytes(outbox_bytes_);
  overflow_armed_ = false;
  overflow_timer_.cancel();
  --context_.websocket_clients;
  context_.connections.erase(id_);
  if (link_) {
    link_->closed = true;
    context_.hub.notify();
  }
  // Aborts whatever is still pending on this connection (a read while a
  // write failed, say), so the last handler runs and frees it.
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().close(ignored);
  if (context_.stopping && context_.connections.empty() && context_.on_all_closed)
    context_.on_all_closed();
}

}  // namespace epviz::serve
