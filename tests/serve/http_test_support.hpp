#pragma once
// Plain HTTP requests to a test server (Boost.Beast's HTTP types), for the
// tests of what the server answers; defined in serve_test_support.cpp.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <boost/beast/http.hpp>

namespace epviz::serve::testing {

// One plain HTTP GET.
boost::beast::http::response<boost::beast::http::string_body> http_get(unsigned short port,
                                                                       const std::string& target);
// A request written by hand, for what the server must refuse (by hand rather
// than with websocket::stream::handshake, which in Boost 1.74 does not hand
// back the response of a declined upgrade): the target, whether it asks for a
// WebSocket upgrade, and the Host and Origin headers, left out when absent;
// `repeated` are further (name, value) lines sent after them as they are.
struct HandRequest {
  std::string target = "/ws";
  bool upgrade = true;
  std::optional<std::string> host = {};
  std::optional<std::string> origin = {};
  std::vector<std::pair<std::string, std::string>> repeated = {};
};
// Sends it and returns the response (101 for an accepted upgrade).
boost::beast::http::response<boost::beast::http::string_body> exchange(unsigned short port,
                                                                       const HandRequest& r);
// A WebSocket upgrade from this server's own host that is expected to be
// refused: the HTTP response.
boost::beast::http::response<boost::beast::http::string_body> refused_upgrade(unsigned short port);

}  // namespace epviz::serve::testing
