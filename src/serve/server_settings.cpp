#include "serve/server_settings.hpp"

#include "io/bad_input.hpp"
#include "io/data_dir.hpp"
#include "io/option_values.hpp"
#include "io/printable.hpp"
#include "serve/origin_policy.hpp"
#include "serve/protocol.hpp"

namespace epviz::serve {

ServerOptions server_options(const ServerSettings& s) {
  ServerOptions so;
  so.bind = s.bind;
  so.port = static_cast<unsigned short>(io::parse_integer("--port", s.port, 0, 65535));
  so.jpeg_quality = int(io::parse_integer("--quality", s.quality, 1, 100));
  so.frame_budget_ms = double(io::parse_integer("--frame-budget", s.frame_budget, 0, 1000));
  // A page asks for its view's size; it gets at most this (a 16384^2 view
  // would be a 1 GiB framebuffer per page), and all pages together are drawn
  // within two such views a round (ServerOptions::pixel_budget).
  const auto x = s.max_view.find('x');
  if (x == std::string::npos)
    throw io::BadInput("--max-view: expected WIDTHxHEIGHT (e.g. 3840x2160), got '" +
                       io::printable(s.max_view, 40) + "'");
  so.max_width = int(io::parse_integer("--max-view", s.max_view.substr(0, x), 16, max_view_pixels));
  so.max_height =
      int(io::parse_integer("--max-view", s.max_view.substr(x + 1), 16, max_view_pixels));
  so.pixel_budget = 2L * so.max_width * so.max_height;
  if (s.image == "jpeg")
    so.image_format = ImageFormat::jpeg;
  else if (s.image == "png")
    so.image_format = ImageFormat::png;
  else
    throw io::BadInput("--image: unknown format '" + s.image + "' (allowed: jpeg, png)");
  so.record_path = s.record;
  for (const std::string& origin : s.allow_origins) {
    const auto normalized = OriginPolicy::normalize_origin(origin);
    if (!normalized)
      throw io::BadInput("--allow-origin: '" + origin +
                         "' is not an origin (allowed: http://HOST[:PORT] or https://HOST[:PORT], "
                         "no path)");
    so.allowed_origins.push_back(*normalized);
  }
  return so;
}

std::filesystem::path find_page() {
  auto page = io::find_data_path("assets/serve.html");
  if (page.empty()) {
    std::string searched;
    for (const auto& dir : io::data_search_path()) {
      searched += ' ';
      searched += (dir / "assets").string();
    }
    throw io::BadInput("the page serve.html is missing; searched:" + searched +
                       " (set EPVIZ_DATA_DIR)");
  }
  return page;
}

bool is_loopback(const std::string& host) {
  return host == "127.0.0.1" || host == "::1" || host == "localhost" || host.rfind("127.", 0) == 0;
}

std::string server_url(const std::string& bind, unsigned port) {
  const std::string host = bind.find(':') != std::string::npos ? "[" + bind + "]" : bind;
  std::string url = "http://";
  url += host;
  url += ':';
  url += std::to_string(port);
  url += '/';
  return url;
}

}  // namespace epviz::serve
