#include "serve_test_support.hpp"

#include "http_test_support.hpp"

#include "support/eventually.hpp"

#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

#include <turbojpeg.h>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

namespace epviz::serve::testing {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;

glm::u8vec4 fake_colour(int inputs) {
  // Successive colours differ by >= 40 in every channel: far more than JPEG's error on a flat image.
  return {static_cast<std::uint8_t>(30 + 50 * inputs), static_cast<std::uint8_t>(200 - 40 * inputs),
          static_cast<std::uint8_t>(90 + 70 * inputs), 255};
}

// ---- FakeSession ----

FakeSession::FakeSession(std::shared_ptr<FakeProbe> probe, bool always_wants)
    : probe_(std::move(probe)), always_wants_(always_wants) {
  probe_->check_thread();
  ++probe_->created;
}

FakeSession::~FakeSession() {
  probe_->check_thread();
  ++probe_->destroyed;
}

void FakeSession::resize(int width, int height) {
  probe_->check_thread();
  image_.width = width;
  image_.height = height;
  dirty_ = true;
}

void FakeSession::input(const render::InputEvent& event) {
  probe_->check_thread();
  ++inputs_;
  ++probe_->inputs;
  dirty_ = true;
  if (event.kind == render::InputEvent::Kind::mouse_move) {
    probe_->last_x = event.x;
    probe_->last_y = event.y;
  }
  if (event.kind != render::InputEvent::Kind::key || !event.down) return;
  if (event.key == "notice")
    notices_.push_back("notice after " + std::to_string(inputs_) + " inputs");
  if (event.key == "download")
    downloads_.push_back({"some/dir/fake.txt", "text/plain", {'h', 'i'}});
  if (event.key == "throw") throw_next_ = true;
  if (event.key == "block") {
    probe_->blocked = true;
    probe_->unblocked.wait_for(expect_within);
  }
}

bool FakeSession::wants_frame() const {
  probe_->check_thread();
  return always_wants_ || dirty_;
}

const render::RgbaImage& FakeSession::render() {
  probe_->check_thread();
  ++probe_->renders;
  if (long(image_.width) * image_.height >= 1'000'000) ++probe_->large_renders;
  if (throw_next_) throw std::runtime_error("fake session asked to fail");
  if (const int cost = probe_->render_ms_per_megapixel; cost > 0)
    std::this_thread::sleep_for(std::chrono::microseconds(
        static_cast<long>(double(image_.width) * image_.height * cost / 1000.0)));
  dirty_ = false;
  const glm::u8vec4 colour = fake_colour(inputs_);
  image_.pixels.resize(static_cast<std::size_t>(image_.width) * image_.height * 4);
  for (std::size_t i = 0; i < image_.pixels.size(); i += 4) {
    image_.pixels[i] = colour.r;
    image_.pixels[i + 1] = colour.g;
    image_.pixels[i + 2] = colour.b;
    image_.pixels[i + 3] = colour.a;
  }
  return image_;
}

void FakeSession::set_view_scale(double scale) {
  probe_->check_thread();
  probe_->view_scale = scale;
}

RenderStages FakeSession::last_render_stages() const {
  return probe_->reports_stages ? fake_stages : RenderStages{};
}

std::vector<Download> FakeSession::take_downloads() {
  probe_->check_thread();
  return std::exchange(downloads_, {});
}

std::vector<std::string> FakeSession::take_notices() {
  probe_->check_thread();
  return std::exchange(notices_, {});
}

std::string FakeSession::controls_json() const {
  probe_->check_thread();
  return nlohmann::json{{"play", {0, 0, image_.width, image_.height}}}.dump();
}

// ---- LogCapture ----

void LogCapture::add(const std::string& line) {
  {
    std::lock_guard lock(mutex_);
    lines_.push_back(line);
  }
  added_.notify_all();
}

bool LogCapture::wait_for(const std::vector<std::string>& parts,
                          std::chrono::milliseconds timeout) {
  auto matches = [&] {
    for (const std::string& line : lines_) {
      bool all = true;
      for (const std::string& part : parts) all = all && line.find(part) != std::string::npos;
      if (all) return true;
    }
    return false;
  };
  std::unique_lock lock(mutex_);
  return added_.wait_for(lock, timeout, matches);
}

std::string LogCapture::all() const {
  std::lock_guard lock(mutex_);
  std::string text;
  for (const std::string& line : lines_) text += line + "\n";
  return text;
}

// ---- TestServer ----

TestServer::TestServer(const std::function<void(ServerOptions&)>& configure, bool always_wants) {
  page = page_dir / "page.html";
  page_text = "<!doctype html><title>epviz test page</title><p>page " +
              page_dir.path().filename().string() + "</p>\n";
  std::ofstream(page, std::ios::binary) << page_text;

  ServerOptions options;
  options.bind = "127.0.0.1";
  options.port = 0;
  options.page = page;
  options.log = [log = log](const std::string& line) { log->add(line); };
  if (configure) configure(options);
  server = std::make_unique<Server>(
      options, [probe = probe] { probe->render_thread = std::this_thread::get_id(); },
      [probe = probe, always_wants] { return std::make_unique<FakeSession>(probe, always_wants); });
  server->start();
}

TestServer::~TestServer() { server.reset(); }

int slowdown() {
  const char* s = std::getenv("EPVIZ_TEST_SLOWDOWN");
  const int n = s ? std::atoi(s) : 1;
  return n >= 1 ? n : 1;
}

bool TestServer::eventually(const std::function<bool()>& condition,
                            std::chrono::milliseconds timeout) {
  return test::eventually(condition, timeout);
}

// ---- TestClient ----

struct TestClient::Connection {
  net::io_context io;
  websocket::stream<beast::tcp_stream> ws{io};
  beast::flat_buffer buffer;
};

TestClient::TestClient(unsigned short port) : c_(std::make_unique<Connection>()) {
  auto& stream = beast::get_lowest_layer(c_->ws);
  stream.expires_after(expect_within);  // bounds the connect and the handshake
  bool done = false;
  beast::error_code ec;
  stream.async_connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port),
                       [&](beast::error_code e) {
                         ec = e;
                         done = true;
                       });
  if (!run_until(done, expect_within) || ec)
    throw std::runtime_error("test client: cannot connect: " + ec.message());
  done = false;
  c_->ws.async_handshake("127.0.0.1:" + std::to_string(port), "/ws", [&](beast::error_code e) {
    ec = e;
    done = true;
  });
  if (!run_until(done, expect_within) || ec)
    throw std::runtime_error("test client: WebSocket handshake failed: " + ec.message());
  stream.expires_never();
  c_->ws.read_message_max(64 * 1024 * 1024);
}

TestClient::~TestClient() {
  beast::error_code ignored;
  beast::get_lowest_layer(c_->ws).socket().close(ignored);
  c_->io.restart();
  c_->io.run_for(expect_within);  // lets the aborted operations finish before the members go
}

bool TestClient::run_until(const bool& done, std::chrono::milliseconds timeout) {
  c_->io.restart();
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done && !c_->io.stopped()) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) break;
    c_->io.run_one_for(deadline - now);
  }
  return done;
}

beast::error_code TestClient::send_text(const std::string& text) {
  bool done = false;
  beast::error_code ec;
  c_->ws.text(true);
  c_->ws.async_write(net::buffer(text), [&](beast::error_code e, std::size_t) {
    ec = e;
    done = true;
  });
  if (!run_until(done, expect_within)) {
    // Never leave the write pending on `text` after returning.
    beast::error_code ignored;
    beast::get_lowest_layer(c_->ws).socket().close(ignored);
    run_until(done, expect_within);
    return beast::error::timeout;
  }
  return ec;
}

void TestClient::start_read() {
  if (read_pending_) return;
  read_pending_ = true;
  read_done_ = false;
  c_->ws.async_read(c_->buffer, [this](beast::error_code ec, std::size_t) {
    read_error_ = ec;
    read_done_ = true;
  });
}

std::optional<ServerMessage> TestClient::receive(std::chrono::milliseconds timeout) {
  start_read();
  if (!run_until(read_done_, timeout)) return std::nullopt;
  read_pending_ = false;
  if (read_error_)
    throw std::runtime_error("test client: connection ended: " + read_error_.message() +
                             " (close code " +
                             std::to_string(static_cast<int>(c_->ws.reason().code)) + ")");
  const auto data = c_->buffer.data();
  const auto* begin = static_cast<const std::uint8_t*>(data.data());
  std::vector<std::uint8_t> bytes(begin, begin + data.size());
  c_->buffer.clear();
  return decode_server_message(bytes);
}

std::optional<Closed> TestClient::wait_closed(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    start_read();
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left <= 0ms || !run_until(read_done_, left)) return std::nullopt;
    read_pending_ = false;
    c_->buffer.clear();
    if (read_error_) {
      Closed closed;
      closed.error = read_error_;
      if (read_error_ == websocket::error::closed)
        closed.code = static_cast<int>(c_->ws.reason().code);
      return closed;
    }
  }
}

void TestClient::close() {
  bool done = false;
  c_->ws.async_close(websocket::close_code::normal, [&](beast::error_code) { done = true; });
  run_until(done, expect_within);
}

void TestClient::drop() {
  auto& socket = beast::get_lowest_layer(c_->ws).socket();
  beast::error_code ignored;
  socket.set_option(net::socket_base::linger(true, 0), ignored);  // RST, not FIN
  socket.close(ignored);
}

// ---- HTTP ----

http::response<http::string_body> http_get(unsigned short port, const std::string& target) {
  net::io_context io;
  beast::tcp_stream stream(io);
  stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port));
  http::request<http::empty_body> request{http::verb::get, target, 11};
  request.set(http::field::host, "127.0.0.1:" + std::to_string(port));
  http::write(stream, request);
  beast::flat_buffer buffer;
  http::response<http::string_body> response;
  http::read(stream, buffer, response);
  beast::error_code ignored;
  stream.socket().shutdown(tcp::socket::shutdown_both, ignored);
  return response;
}

http::response<http::string_body> exchange(unsigned short port, const HandRequest& r) {
  net::io_context io;
  beast::tcp_stream stream(io);
  stream.expires_after(expect_within);
  stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port));
  http::request<http::empty_body> request{http::verb::get, r.target, 11};
  if (r.host) request.set(http::field::host, *r.host);
  if (r.origin) request.set(http::field::origin, *r.origin);
  for (const auto& [name, value] : r.repeated) request.insert(name, value);
  if (r.upgrade) {
    request.set(http::field::connection, "Upgrade");
    request.set(http::field::upgrade, "websocket");
    request.set(http::field::sec_websocket_version, "13");
    request.set(http::field::sec_websocket_key, "AAAAAAAAAAAAAAAAAAAAAA==");
  }
  http::write(stream, request);
  beast::flat_buffer buffer;
  http::response_parser<http::string_body> parser;
  http::read_header(stream, buffer, parser);
  if (parser.get().result() != http::status::switching_protocols)
    http::read(stream, buffer, parser);
  return parser.release();
}

http::response<http::string_body> refused_upgrade(unsigned short port) {
  return exchange(port, {.host = "127.0.0.1:" + std::to_string(port)});
}

// ---- JPEG ----

render::RgbaImage decode_jpeg(const std::vector<std::uint8_t>& jpeg) {
  tjhandle handle = tjInitDecompress();
  if (!handle) throw std::runtime_error("tjInitDecompress failed");
  render::RgbaImage image;
  int subsampling = 0, colourspace = 0;
  const auto size = static_cast<unsigned long>(jpeg.size());
  bool ok = tjDecompressHeader3(handle, jpeg.data(), size, &image.width, &image.height,
                                &subsampling, &colourspace) == 0;
  if (ok) {
    image.pixels.resize(static_cast<std::size_t>(image.width) * image.height * 4);
    ok = tjDecompress2(handle, jpeg.data(), size, image.pixels.data(), image.width, 0, image.height,
                       TJPF_RGBA, 0) == 0;
  }
  const std::string error = ok ? "" : tjGetErrorStr2(handle);
  tjDestroy(handle);
  if (!ok) throw std::runtime_error("JPEG decode failed: " + error);
  return image;
}

// ---- ReadingPage ----

ReadingPage::ReadingPage(unsigned short port, int width, int height) : client_(port) {
  client_.send(resize(width, height));
  thread_ = std::thread([this] { run(); });
}

ReadingPage::~ReadingPage() {
  stop_ = true;
  thread_.join();
}

std::vector<std::chrono::steady_clock::time_point> ReadingPage::arrivals() const {
  std::lock_guard lock(mutex_);
  return arrivals_;
}

std::pair<int, int> ReadingPage::last_size() const {
  std::lock_guard lock(mutex_);
  return last_size_;
}

void ReadingPage::run() {
  while (!stop_) {
    std::optional<ServerMessage> m;
    try {
      m = client_.receive(100ms);
    } catch (const std::exception&) {
      return;  // the connection ended
    }
    if (!m || m->header.value("kind", "") != "frame") continue;
    {
      std::lock_guard lock(mutex_);
      arrivals_.push_back(std::chrono::steady_clock::now());
      last_size_ = {m->header["width"].get<int>(), m->header["height"].get<int>()};
    }
    client_.send(ack(m->header["frame"].get<std::int64_t>()));
  }
}

}  // namespace epviz::serve::testing
