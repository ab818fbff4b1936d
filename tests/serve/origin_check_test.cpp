// The server refuses, with 403 and one log line, WebSocket upgrades from
// other web pages (their Origin) and any request whose Host is not this
// server's (DNS rebinding), over real sockets with hand-written requests.
#include <gtest/gtest.h>

#include "http_test_support.hpp"
#include "serve_test_support.hpp"
#include "support/cli.hpp"

namespace epviz::serve::testing {
namespace {

namespace http = boost::beast::http;

std::string own(unsigned short port) { return "127.0.0.1:" + std::to_string(port); }

TEST(ServeOrigin, OwnPageUpgradesOtherPagesGet403) {
  TestServer server;
  const unsigned short port = server.port();
  const std::string p = std::to_string(port);
  for (const std::string& origin : {"http://127.0.0.1:" + p, "http://localhost:" + p}) {
    SCOPED_TRACE(origin);
    EXPECT_EQ(exchange(port, {.host = own(port), .origin = origin}).result(),
              http::status::switching_protocols);
  }
  // Without Origin the client is no web page (browsers always send one).
  EXPECT_EQ(exchange(port, {.host = own(port)}).result(), http::status::switching_protocols);

  for (const std::string& origin :
       {std::string("http://evil.example"), "http://evil.example:" + p, std::string("null"),
        "https://127.0.0.1:" + p, "http://127.0.0.1:" + std::to_string(port + 1)}) {
    SCOPED_TRACE(origin);
    const auto response = exchange(port, {.host = own(port), .origin = origin});
    EXPECT_EQ(response.result(), http::status::forbidden);
    EXPECT_NE(response.body().find("is not this server's page"), std::string::npos)
        << response.body();
  }
  EXPECT_TRUE(server.log->wait_for({"refused a request for /ws", "Origin 'http://evil.example'"}))
      << server.log->all();
  EXPECT_EQ(server.server->stats().connections_accepted, 3) << "a refused upgrade was accepted";
}

TEST(ServeOrigin, ForgedHostGets403ForThePageAndTheSocket) {
  TestServer server;
  const unsigned short port = server.port();
  const std::string rebound = "evil.example:" + std::to_string(port);
  const auto page = exchange(port, {.target = "/", .upgrade = false, .host = rebound});
  EXPECT_EQ(page.result(), http::status::forbidden);
  EXPECT_EQ(page.body().find("epviz test page"), std::string::npos) << "the page leaked";
  EXPECT_NE(page.body().find("does not name this server"), std::string::npos) << page.body();
  // Even with an origin that matches the forged host, as a rebound page would send.
  const auto socket = exchange(port, {.host = rebound, .origin = "http://" + rebound});
  EXPECT_EQ(socket.result(), http::status::forbidden);
  EXPECT_EQ(exchange(port, {.target = "/", .upgrade = false}).result(), http::status::forbidden)
      << "no Host at all";
  EXPECT_TRUE(server.log->wait_for({"refused a request for /", "Host 'evil.example:"}))
      << server.log->all();
  EXPECT_EQ(server.server->stats().connections_accepted, 0);

  EXPECT_EQ(exchange(port, {.target = "/", .upgrade = false, .host = own(port)}).result(),
            http::status::ok);
  EXPECT_EQ(
      exchange(port, {.target = "/", .upgrade = false, .host = "localhost:" + std::to_string(port)})
          .result(),
      http::status::ok);
}

// Which copy of a repeated header counts is not this server's choice: a proxy
// in front may have read the other one. Each order is tried, so a server that
// checks only the first (or only the last) copy lets one of them through.
TEST(ServeOrigin, ARepeatedHostOrOriginIsABadRequest) {
  TestServer server;
  const unsigned short port = server.port();
  const std::string good_origin = "http://" + own(port);
  const std::string evil = "evil.example:" + std::to_string(port);
  for (const auto& [first, second] : {std::pair(own(port), evil), std::pair(evil, own(port))}) {
    SCOPED_TRACE(first + " then " + second);
    const auto page = exchange(
        port, {.target = "/", .upgrade = false, .host = first, .repeated = {{"Host", second}}});
    EXPECT_EQ(page.result(), http::status::bad_request) << page.body();
    EXPECT_NE(page.body().find("more than one Host header"), std::string::npos) << page.body();
  }
  for (const auto& [first, second] :
       {std::pair(good_origin, "http://" + evil), std::pair("http://" + evil, good_origin)}) {
    SCOPED_TRACE(first + " then " + second);
    const auto socket =
        exchange(port, {.host = own(port), .origin = first, .repeated = {{"Origin", second}}});
    EXPECT_EQ(socket.result(), http::status::bad_request) << socket.body();
    EXPECT_NE(socket.body().find("more than one Origin header"), std::string::npos)
        << socket.body();
  }
  // The same copy twice is no less ambiguous to a reader that joins them.
  EXPECT_EQ(
      exchange(port,
               {.host = own(port), .origin = good_origin, .repeated = {{"Origin", good_origin}}})
          .result(),
      http::status::bad_request);
  EXPECT_TRUE(server.log->wait_for({"refused a request for /ws", "more than one Origin header"}))
      << server.log->all();
  EXPECT_EQ(server.server->stats().connections_accepted, 0);
}

TEST(ServeOrigin, AllowOriginLetsThatPageIn) {
  TestServer server([](ServerOptions& o) { o.allowed_origins = {"https://viz.example.org"}; });
  const unsigned short port = server.port();
  EXPECT_EQ(exchange(port, {.host = own(port), .origin = "https://viz.example.org"}).result(),
            http::status::switching_protocols);
  EXPECT_EQ(exchange(port, {.host = own(port), .origin = "https://other.example.org"}).result(),
            http::status::forbidden);
}

TEST(ServeOrigin, AMalformedAllowOriginIsABadOption) {
  const test::TempDir dir;
  test::expect_bad_input(test::run_epviz("serve --port 0 --allow-origin 'http://x/path'", dir),
                         "--allow-origin: 'http://x/path' is not an origin");
}

}  // namespace
}  // namespace epviz::serve::testing
