#include "app/serve_command.hpp"

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/cli_values.hpp"
#include "app/gl_option.hpp"
#include "io/bad_input.hpp"
#include "io/data_dir.hpp"
#include "io/printable.hpp"
#include "live/live_session.hpp"
#include "render/gl_choice.hpp"
#include "serve/origin_policy.hpp"
#include "serve/protocol.hpp"
#include "serve/server.hpp"

namespace epviz::app {
namespace {

struct ServeOptions {
  std::string job, bind = "127.0.0.1", gl, image = "jpeg", save_dir, record;
  std::string port = "8080", quality = "85", max_view = "3840x2160";
  std::vector<std::string> allow_origins;
  bool play = false;
};

serve::Server* g_server = nullptr;  // for the signal handler only

extern "C" void on_stop_signal(int) {
  if (g_server) g_server->request_stop();
}

bool is_loopback(const std::string& host) {
  return host == "127.0.0.1" || host == "::1" || host == "localhost" || host.rfind("127.", 0) == 0;
}

int run_serve(const ServeOptions& o) {
  serve::ServerOptions so;
  so.bind = o.bind;
  so.port = static_cast<unsigned short>(parse_integer("--port", o.port, 0, 65535));
  so.jpeg_quality = int(parse_integer("--quality", o.quality, 1, 100));
  // A page asks for its view's size; it gets at most this (a 16384^2 view
  // would be a 1 GiB framebuffer per page), and all pages together are drawn
  // within two such views a round (ServerOptions::pixel_budget).
  const auto x = o.max_view.find('x');
  if (x == std::string::npos)
    throw io::BadInput("--max-view: expected WIDTHxHEIGHT (e.g. 3840x2160), got '" +
                       io::printable(o.max_view, 40) + "'");
  so.max_width =
      int(parse_integer("--max-view", o.max_view.substr(0, x), 16, serve::max_view_pixels));
  so.max_height =
      int(parse_integer("--max-view", o.max_view.substr(x + 1), 16, serve::max_view_pixels));
  so.pixel_budget = 2L * so.max_width * so.max_height;
  if (o.image == "jpeg")
    so.image_format = serve::ImageFormat::jpeg;
  else if (o.image == "png")
    so.image_format = serve::ImageFormat::png;
  else
    throw io::BadInput("--image: unknown format '" + o.image + "' (allowed: jpeg, png)");
  so.page = io::find_data_path("assets/serve.html");
  if (so.page.empty()) {
    std::string searched;
    for (const auto& dir : io::data_search_path()) searched += " " + (dir / "assets").string();
    throw io::BadInput("the page serve.html is missing; searched:" + searched +
                       " (set EPVIZ_DATA_DIR)");
  }
  so.record_path = o.record;
  for (const std::string& origin : o.allow_origins) {
    const auto normalized = serve::OriginPolicy::normalize_origin(origin);
    if (!normalized)
      throw io::BadInput("--allow-origin: '" + origin +
                         "' is not an origin (allowed: http://HOST[:PORT] or https://HOST[:PORT], "
                         "no path)");
    so.allowed_origins.push_back(*normalized);
  }
  so.log = [](const std::string& line) { std::fprintf(stderr, "epviz serve: %s\n", line.c_str()); };

  const render::GlChoice gl_choice(o.gl);

  live::SessionOptions session;
  session.initial = o.job.empty() ? live::preset_from_jobs(physics::Case::kovalevskaya)
                                  : live::setup_from_job_file(o.job);
  session.presets = live::preset_from_jobs;
  session.save_dir = o.save_dir;
  session.start_playing = o.play;
  try {
    live::LiveScene check(
        session.initial);  // a job the scene cannot run is an error now, not per connection
  } catch (const std::exception& e) {
    throw io::BadInput((o.job.empty() ? std::string("default scene") : o.job) + ": " + e.what());
  }

  // The GL context belongs to the render thread, which creates it.
  std::unique_ptr<render::GlContext> gl;
  serve::Server server(
      so, [&] { gl = gl_choice.open(); },
      [&]() -> std::unique_ptr<serve::Session> {
        return std::make_unique<live::LiveSession>(*gl, session);
      });
  server.start();
  if (!is_loopback(o.bind))
    std::fprintf(
        stderr,
        "epviz serve: warning: listening on %s: anyone who can reach this address can use the "
        "server (and write files to --save-dir if given)\n",
        o.bind.c_str());
  const std::string host = o.bind.find(':') != std::string::npos ? "[" + o.bind + "]" : o.bind;
  std::printf("epviz serve: http://%s:%u/  (Ctrl+C to stop)\n", host.c_str(),
              unsigned(server.port()));
  std::fflush(stdout);

  g_server = &server;
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  server.wait();
  g_server = nullptr;
  const serve::ServerStats stats = server.stats();
  std::fprintf(stderr, "epviz serve: stopped after %ld connections, %ld frames sent\n",
               stats.connections_accepted, stats.frames_sent);
  return 0;
}

}  // namespace

std::function<int()> add_serve_command(CLI::App& app) {
  auto o = std::make_shared<ServeOptions>();
  CLI::App* cmd =
      app.add_subcommand("serve", "Serve the renderer live to a web browser (one scene per tab)");
  cmd->add_option("job", o->job, "render job to start from (default: the Kovalevskaya top)");
  cmd->add_option("--port", o->port, "TCP port (0: any free port)")->capture_default_str();
  cmd->add_option("--bind", o->bind,
                  "address to listen on; other than loopback is reachable from the network")
      ->capture_default_str();
  add_gl_option(*cmd, o->gl);
  cmd->add_option("--image", o->image, "frame encoding: jpeg or png")->capture_default_str();
  cmd->add_option("--quality", o->quality, "JPEG quality 1..100")->capture_default_str();
  cmd->add_option("--save-dir", o->save_dir,
                  "also write saved frames and jobs here (default: browser downloads only)");
  cmd->add_option("--allow-origin", o->allow_origins,
                  "also accept WebSocket connections from pages of this origin "
                  "(http[s]://HOST[:PORT]; repeatable); by default only the server's own page")
      ->allow_extra_args(false);
  cmd->add_option("--max-view", o->max_view,
                  "WIDTHxHEIGHT: the largest view a page gets (each 16..16384); larger requests "
                  "are drawn at this size")
      ->capture_default_str();
  cmd->add_flag("--play", o->play, "start playing");
  cmd->add_option("--record", o->record,
                  "record the first connection's events (replayed by the tests)");
  return [o] { return run_serve(*o); };
}

}  // namespace epviz::app
