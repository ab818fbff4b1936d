// `epviz serve`'s settings from their text: each checked, a mistake naming
// its option, the view budget following --max-view.
#include <gtest/gtest.h>

#include "io/bad_input.hpp"
#include "serve/origin_policy.hpp"
#include "serve/protocol.hpp"
#include "serve/server_settings.hpp"
#include "support/errors.hpp"

namespace epviz::serve {
namespace {

TEST(ServerSettings, TextToOptions) {
  const auto o = server_options({.port = "0",
                                 .quality = "60",
                                 .frame_budget = "25",
                                 .max_view = "1920x1080",
                                 .image = "png",
                                 .allow_origins = {"HTTP://Example.org:8000"},
                                 .record = ""});
  EXPECT_EQ(o.port, 0);
  EXPECT_EQ(o.jpeg_quality, 60);
  EXPECT_EQ(o.frame_budget_ms, 25.0);
  EXPECT_EQ(o.max_width, 1920);
  EXPECT_EQ(o.max_height, 1080);
  EXPECT_EQ(o.pixel_budget, 2L * 1920 * 1080);
  EXPECT_EQ(o.image_format, ImageFormat::png);
  ASSERT_EQ(o.allowed_origins.size(), 1u);
  EXPECT_EQ(o.allowed_origins[0], *OriginPolicy::normalize_origin("HTTP://Example.org:8000"));
  // The defaults are those of a server's own options.
  const auto d = server_options({});
  EXPECT_EQ(d.port, ServerOptions{}.port);
  EXPECT_EQ(d.max_width, ServerOptions{}.max_width);
  EXPECT_EQ(d.pixel_budget, ServerOptions{}.pixel_budget);
  // Except adaptive resolution, off for a server built in code but on for
  // the command, which users run: smaller frames while moving, sharp at rest.
  EXPECT_EQ(d.frame_budget_ms, 18.0);
  ServerSettings off;
  off.frame_budget = "0";
  EXPECT_EQ(server_options(off).frame_budget_ms, 0.0);
}

TEST(ServerSettings, MistakesNameTheirOption) {
  const auto error = [](auto change) {
    ServerSettings s;
    change(s);
    return test::error_of<io::BadInput>([&] { server_options(s); });
  };
  EXPECT_EQ(error([](auto& s) { s.port = "65536"; }).rfind("--port: ", 0), 0u);
  EXPECT_EQ(error([](auto& s) { s.quality = "0"; }).rfind("--quality: ", 0), 0u);
  EXPECT_EQ(error([](auto& s) { s.frame_budget = "-1"; }).rfind("--frame-budget: ", 0), 0u);
  EXPECT_EQ(error([](auto& s) { s.frame_budget = "1001"; }).rfind("--frame-budget: ", 0), 0u);
  EXPECT_EQ(
      error([](auto& s) { s.max_view = "1920"; }).rfind("--max-view: expected WIDTHxHEIGHT", 0),
      0u);
  EXPECT_EQ(error([](auto& s) { s.max_view = "8x1080"; }).rfind("--max-view: ", 0), 0u);
  const auto too_big = "1920x" + std::to_string(max_view_pixels + 1);
  EXPECT_EQ(error([&](auto& s) { s.max_view = too_big; }).rfind("--max-view: ", 0), 0u);
  EXPECT_EQ(error([](auto& s) { s.image = "webp"; }),
            "--image: unknown format 'webp' (allowed: jpeg, png)");
  EXPECT_EQ(error([](auto& s) {
              s.allow_origins = {"http://a.org/path"};
            }).rfind("--allow-origin: 'http://a.org/path' is not an origin", 0),
            0u);
}

TEST(ServerSettings, LoopbackAndUrl) {
  for (const char* host : {"127.0.0.1", "127.1.2.3", "::1", "localhost"})
    EXPECT_TRUE(is_loopback(host)) << host;
  for (const char* host : {"0.0.0.0", "::", "192.168.1.2", "example.org"})
    EXPECT_FALSE(is_loopback(host)) << host;
  EXPECT_EQ(server_url("127.0.0.1", 8080), "http://127.0.0.1:8080/");
  EXPECT_EQ(server_url("::1", 80), "http://[::1]:80/");
}

}  // namespace
}  // namespace epviz::serve
