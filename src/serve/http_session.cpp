#include "serve/http_session.hpp"

#include <chrono>
#include <fstream>
#include <sstream>

#include <boost/beast/websocket/rfc6455.hpp>

#include "io/json_text.hpp"
#include "serve/websocket_connection.hpp"

namespace epviz::serve {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;

namespace {

// Bounds for a request: the page only ever sends small GETs, so anything
// bigger is not ours and is cut off before it costs memory or a slot.
constexpr auto request_timeout = std::chrono::seconds(30);
constexpr std::uint32_t header_limit = 16 * 1024;
constexpr std::uint64_t body_limit = 4 * 1024;

std::string path_of(const http::request<http::string_body>& request) {
  const auto target = request.target();
  std::string path(target.data(), target.size());
  if (const auto query = path.find('?'); query != std::string::npos) path.resize(query);
  return path;
}

std::optional<std::string> read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return std::move(text).str();
}

// A second Host or Origin makes the request ambiguous: a proxy and this
// server could each believe a different copy, so which one is checked must
// not be a choice made here. HTTP says such a request is malformed (400).
std::optional<std::string> repeated_header(const http::request<http::string_body>& request) {
  for (const http::field field : {http::field::host, http::field::origin}) {
    if (request.count(field) < 2) continue;
    const auto name = http::to_string(field);
    return "more than one " + std::string(name.data(), name.size()) + " header";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> HttpSession::refusal(const Request& request) const {
  const OriginPolicy& policy = *context_.origins;
  const auto host = request.find(http::field::host);
  const auto view = [](boost::beast::string_view v) {
    return std::string_view(v.data(), v.size());
  };
  const std::string_view host_text =
      host == request.end() ? std::string_view() : view(host->value());
  if (auto problem = policy.host_problem(host_text)) return problem;
  if (!websocket::is_upgrade(request)) return std::nullopt;
  const auto origin = request.find(http::field::origin);
  return policy.origin_problem(origin != request.end(),
                               origin == request.end() ? std::string_view() : view(origin->value()),
                               host_text);
}

HttpSession::HttpSession(boost::asio::ip::tcp::socket socket, NetworkContext& context)
    : stream_(std::move(socket)), context_(context) {}

void HttpSession::start() { read_request(); }

void HttpSession::read_request() {
  parser_.emplace();
  parser_->header_limit(header_limit);
  parser_->body_limit(body_limit);
  stream_.expires_after(request_timeout);
  http::async_read(
      stream_, buffer_, *parser_,
      [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_request(ec); });
}

void HttpSession::on_request(beast::error_code ec) {
  // end_of_stream: the browser closed a keep-alive connection; any other
  // error (timeout, garbage) just drops it, there is nobody to tell.
  if (ec) {
    beast::error_code ignored;
    stream_.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_send, ignored);
    return;
  }
  Request request = parser_->release();
  const std::string path = path_of(request);
  std::optional<std::string> problem = repeated_header(request);
  const bool malformed = problem.has_value();
  if (!malformed) problem = refusal(request);
  if (problem) {
    context_.log("refused a request for " + std::string(path.substr(0, 100)) + " from " +
                 peer_of(stream_) + ": " + *problem);
    return respond(request, malformed ? http::status::bad_request : http::status::forbidden,
                   "text/plain", *problem + "\n");
  }
  if (websocket::is_upgrade(request)) {
    if (path == "/ws") return upgrade(std::move(request));
    return respond(request, http::status::not_found, "text/plain",
                   "no WebSocket at " + path + "; use /ws\n");
  }
  if (request.method() != http::verb::get)
    return respond(request, http::status::method_not_allowed, "text/plain", "only GET is served\n");
  if (path == "/stats")
    // The counters and where frames' time goes; harmless to show, and behind the same Host check.
    return respond(request, http::status::ok, "application/json",
                   io::json_text(stats_json(context_.counters)) + "\n");
  if (path != "/")
    return respond(request, http::status::not_found, "text/plain", "not found: " + path + "\n");
  std::optional<std::string> page = read_file(context_.options.page);
  if (!page) {
    context_.log("cannot read the page " + context_.options.page.string());
    return respond(request, http::status::internal_server_error, "text/plain",
                   "the page file cannot be read\n");
  }
  respond(request, http::status::ok, "text/html; charset=utf-8", std::move(*page));
}

void HttpSession::upgrade(Request request) {
  const int limit = context_.options.max_clients;
  if (context_.stopping)
    return respond(request, http::status::service_unavailable, "text/plain",
                   "the server is stopping\n");
  if (context_.websocket_clients >= limit) {
    context_.log("refused a connection: " + std::to_string(limit) +
                 " clients already connected (max_clients)");
    return respond(request, http::status::service_unavailable, "text/plain",
                   "too many clients: this server takes at most " + std::to_string(limit) +
                       " connections at a time; close another tab and reload\n");
  }
  const long id = context_.next_id++;
  ++context_.websocket_clients;
  ++context_.counters.connections_accepted;
  stream_.expires_never();
  auto connection = std::make_shared<WebSocketConnection>(std::move(stream_), context_, id);
  context_.connections.emplace(id, connection);
  connection->start(std::move(request));
}

void HttpSession::respond(const Request& request, http::status status, const char* content_type,
                          std::string body) {
  auto response = std::make_shared<Response>(status, request.version());
  response->set(http::field::server, "epviz");
  response->set(http::field::content_type, content_type);
  // The page is a development tool's UI and changes with the binary: never
  // let a browser show a stale copy.
  response->set(http::field::cache_control, "no-store");
  response->keep_alive(request.keep_alive() && status != http::status::service_unavailable);
  response->body() = std::move(body);
  response->prepare_payload();
  stream_.expires_after(request_timeout);
  http::async_write(
      stream_, *response, [self = shared_from_this(), response](beast::error_code ec, std::size_t) {
        if (ec) return;
        if (response->keep_alive()) return self->read_request();
        beast::error_code ignored;
        self->stream_.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_send, ignored);
      });
}

}  // namespace epviz::serve
