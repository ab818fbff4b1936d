#include "app/serve_command.hpp"

#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/gl_option.hpp"
#include "io/bad_input.hpp"
#include "live/live_session.hpp"
#include "render/gl_choice.hpp"
#include "serve/server.hpp"
#include "serve/server_settings.hpp"

namespace epviz::app {
namespace {

struct ServeOptions {
  std::string job, gl, save_dir;
  serve::ServerSettings server;
  bool play = false;
};

serve::Server* g_server = nullptr;  // for the signal handler only

extern "C" void on_stop_signal(int) {
  if (g_server) g_server->request_stop();
}

int run_serve(const ServeOptions& o) {
  serve::ServerOptions so = serve::server_options(o.server);
  so.page = serve::find_page();
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
  if (!serve::is_loopback(o.server.bind))
    std::fprintf(
        stderr,
        "epviz serve: warning: listening on %s: anyone who can reach this address can use the "
        "server (and write files to --save-dir if given)\n",
        o.server.bind.c_str());
  std::printf("epviz serve: %s  (Ctrl+C to stop)\n",
              serve::server_url(o.server.bind, server.port()).c_str());
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

std::function<int()> add_serve_command(cli::Command app) {
  auto o = std::make_shared<ServeOptions>();
  cli::Command cmd =
      app.add_subcommand("serve", "Serve the renderer live to a web browser (one scene per tab)");
  cmd.add_option("job", o->job, "render job to start from (default: the Kovalevskaya top)");
  cmd.add_option("--port", o->server.port, "TCP port (0: any free port)").show_default();
  cmd.add_option("--bind", o->server.bind,
                 "address to listen on; other than loopback is reachable from the network")
      .show_default();
  add_gl_option(cmd, o->gl);
  cmd.add_option("--image", o->server.image, "frame encoding: jpeg or png").show_default();
  cmd.add_option("--quality", o->server.quality, "JPEG quality 1..100").show_default();
  cmd.add_option("--frame-budget", o->server.frame_budget,
                 "ms a frame may take (to draw and encode, or for the browser to decode); "
                 "views are drawn smaller while frames take longer, and sharp again at rest "
                 "(0: always full size)")
      .show_default();
  cmd.add_option("--save-dir", o->save_dir,
                 "also write saved frames and jobs here (default: browser downloads only)");
  cmd.add_option("--allow-origin", o->server.allow_origins,
                 "also accept WebSocket connections from pages of this origin "
                 "(http[s]://HOST[:PORT]; repeatable); by default only the server's own page")
      .one_value_per_use();
  cmd.add_option("--max-view", o->server.max_view,
                 "WIDTHxHEIGHT: the largest view a page gets (each 16..16384); larger requests "
                 "are drawn at this size")
      .show_default();
  cmd.add_flag("--play", o->play, "start playing");
  cmd.add_option("--record", o->server.record,
                 "record the first connection's events (replayed by the tests)");
  return [o] { return run_serve(*o); };
}

}  // namespace epviz::app
