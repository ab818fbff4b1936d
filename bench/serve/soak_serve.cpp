// The serve soak: `epviz serve --play` in a child process, and pages that
// all ask for the largest view a page may ask for (16384 x 16384, which the
// server draws at --max-view's size) and play, read and acknowledge frames
// for a while; ten rounds by default. It fails (exit 1) when the server dies
// of a signal or exits with an error, or when a page gets no frame.
//
//   epviz_serve_soak [ROUNDS [SECONDS [PAGES]]]      (default 10 5 15)
//
// Wall-clock limits make this a benchmark, not a test: on the 2-core
// development machine a round of 15 pages at 3840x2160 renders a few frames
// a second in all.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "serve/protocol.hpp"

namespace {

namespace beast = boost::beast;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using Clock = std::chrono::steady_clock;

struct Server {
  pid_t pid = -1;
  unsigned short port = 0;
};

// Starts `epviz serve --port 0 --play` and reads the port from its first line.
Server start_server() {
  int out[2];
  if (::pipe(out) != 0) std::exit(2);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(out[1], STDOUT_FILENO);
    ::close(out[0]);
    ::close(out[1]);
    ::execl(EPVIZ_BINARY, EPVIZ_BINARY, "serve", "--port", "0", "--play",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(out[1]);
  std::string line;
  char c = 0;
  while (::read(out[0], &c, 1) == 1 && c != '\n') line += c;
  ::close(out[0]);
  // "epviz serve: http://127.0.0.1:PORT/  (Ctrl+C to stop)"
  const auto colon = line.rfind(':', line.find("/  "));
  const int port = colon == std::string::npos ? 0 : std::atoi(line.c_str() + colon + 1);
  if (port <= 0) {
    std::fprintf(stderr, "soak: the server did not say its port: '%s'\n", line.c_str());
    ::kill(pid, SIGKILL);
    std::exit(2);
  }
  return {pid, static_cast<unsigned short>(port)};
}

struct PageResult {
  int frames = 0;
  int width = 0, height = 0;  // of the last frame
  std::string error;
};

// One page: asks for the largest view, then reads and acknowledges frames
// until the connection ends.
PageResult page(unsigned short port, Clock::time_point until) {
  PageResult r;
  try {
    net::io_context io;
    beast::websocket::stream<tcp::socket> ws(io);
    tcp::resolver resolver(io);
    net::connect(ws.next_layer(), resolver.resolve("127.0.0.1", std::to_string(port)));
    ws.handshake("127.0.0.1:" + std::to_string(port), "/ws");
    ws.read_message_max(256u << 20);
    const int largest = epviz::serve::max_view_pixels;
    ws.text(true);
    ws.write(net::buffer(
        nlohmann::json{{"type", "resize"}, {"width", largest}, {"height", largest}}.dump()));
    // Until the server stops (the soak ends it at `until`): an error before
    // then is the page's failure.
    for (;;) {
      beast::flat_buffer buffer;
      beast::error_code ec;
      ws.read(buffer, ec);
      if (ec) {
        if (Clock::now() < until) r.error = ec.message();
        break;
      }
      const auto data = static_cast<const std::uint8_t*>(buffer.data().data());
      const auto m = epviz::serve::decode_server_message({data, buffer.size()});
      if (m.header.value("kind", "") != "frame") continue;
      ++r.frames;
      r.width = m.header["width"];
      r.height = m.header["height"];
      ws.text(true);
      ws.write(net::buffer(nlohmann::json{{"type", "ack"}, {"frame", m.header["frame"]}}.dump()));
    }
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 10;
  const int seconds = argc > 2 ? std::atoi(argv[2]) : 5;
  const int pages = argc > 3 ? std::atoi(argv[3]) : 15;
  bool failed = false;
  for (int round = 1; round <= rounds; ++round) {
    const Server server = start_server();
    const auto until = Clock::now() + std::chrono::seconds(seconds);
    std::vector<PageResult> results(static_cast<std::size_t>(pages));
    std::vector<std::thread> threads;
    for (int p = 0; p < pages; ++p)
      threads.emplace_back([&, p] { results[std::size_t(p)] = page(server.port, until); });
    std::this_thread::sleep_until(until);
    ::kill(server.pid, SIGTERM);  // a server that died already is reaped below as it died
    int status = 0;
    bool hung = true;
    for (int tries = 0; tries < 200 && hung; ++tries) {
      hung = ::waitpid(server.pid, &status, WNOHANG) == 0;
      if (hung) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (hung) {  // 20 s after SIGTERM: stuck
      ::kill(server.pid, SIGKILL);
      ::waitpid(server.pid, &status, 0);
      status = -1;
    }
    for (auto& t : threads) t.join();
    int least = 1 << 30, most = 0, width = 0, height = 0;
    std::string error;
    for (const auto& r : results) {
      least = std::min(least, r.frames);
      most = std::max(most, r.frames);
      width = std::max(width, r.width);
      height = std::max(height, r.height);
      if (!r.error.empty() && error.empty()) error = r.error;
    }
    const bool clean = !hung && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    std::printf("round %d: %d pages, frames per page %d..%d, largest frame %dx%d, server %s%s%s\n",
                round, pages, least, most, width, height,
                clean  ? "exited cleanly"
                : hung ? "HUNG after SIGTERM"
                       : (WIFSIGNALED(status) ? "DIED of a signal" : "exited with an error"),
                error.empty() ? "" : "; a page: ", error.c_str());
    std::fflush(stdout);
    if (!clean || least == 0) failed = true;
  }
  std::printf("%s\n", failed ? "soak: FAILED" : "soak: no crash, every page got frames");
  return failed ? 1 : 0;
}
