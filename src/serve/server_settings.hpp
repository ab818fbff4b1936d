#pragma once
// The server's settings as `epviz serve` takes them, as text: each checked
// into ServerOptions, a mistake io::BadInput naming the option and what is
// allowed, before the server starts.
#include <filesystem>
#include <string>
#include <vector>

#include "serve/server.hpp"

namespace epviz::serve {

struct ServerSettings {
  std::string bind = "127.0.0.1";
  std::string port = "8080";   // 0: any free port
  std::string quality = "85";  // JPEG quality 1..100
  // Adaptive resolution's budget in ms per frame (ServerOptions::frame_budget_ms), 0..1000; 0: off.
  // 18 ms: about 55 frames/s where drawing or decoding allows, measured in docs/serve.md.
  std::string frame_budget = "18";
  std::string max_view = "3840x2160";  // WIDTHxHEIGHT, each 16..max_view_pixels
  std::string image = "jpeg";          // or png
  std::vector<std::string> allow_origins;
  std::string record;  // record the first connection's events here ("" for none)
};

// Everything but the page (find_page) and the log.
ServerOptions server_options(const ServerSettings& settings);

// The page served at "/" (assets/serve.html on io's data search path);
// io::BadInput naming the folders searched when it is missing.
std::filesystem::path find_page();

// Whether `host` is reachable from this machine only (a loopback address).
bool is_loopback(const std::string& host);

// "http://HOST:PORT/", an IPv6 address in brackets.
std::string server_url(const std::string& bind, unsigned port);

}  // namespace epviz::serve
