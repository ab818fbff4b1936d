#pragma once
// A freshly accepted TCP connection speaking HTTP: answers 400 to a request
// with more than one Host or Origin header, refuses (403) requests
// whose Host does not name this server and upgrades from other pages'
// origins (OriginPolicy), serves the page at "/", 404 elsewhere, and hands an upgrade request for "/ws" to a new
// WebSocketConnection (or refuses it with 503 when max_clients are connected).
#include <memory>
#include <optional>
#include <string>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include "serve/network_context.hpp"

namespace epviz::serve {

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(boost::asio::ip::tcp::socket socket, NetworkContext& context);
  void start();  // network thread

 private:
  using Request = boost::beast::http::request<boost::beast::http::string_body>;
  using Response = boost::beast::http::response<boost::beast::http::string_body>;

  // Why the request is refused (Host, and Origin for an upgrade), or nullopt.
  std::optional<std::string> refusal(const Request& request) const;
  void read_request();
  void on_request(boost::beast::error_code ec);
  void upgrade(Request request);
  void respond(const Request& request, boost::beast::http::status status, const char* content_type,
               std::string body);

  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  NetworkContext& context_;
};

}  // namespace epviz::serve
