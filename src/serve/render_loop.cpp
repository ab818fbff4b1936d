#include "serve/render_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <type_traits>

namespace epviz::serve {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Smaller than this and a view is useless (and some encoders dislike tiny images).
constexpr int min_view_pixels = 16;

int scaled(int size, double scale) { return std::max(min_view_pixels, int(size * scale)); }

std::string describe_current_exception() {
  try {
    throw;
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "an exception that is not a std::exception";
  }
}

}  // namespace

RenderLoop::RenderLoop(const ServerOptions& options, RenderHub& hub, SessionFactory make_session,
                       const ServerLog& log, ServerCounters& counters)
    : options_(options),
      hub_(hub),
      make_session_(std::move(make_session)),
      log_(log),
      counters_(counters),
      encoder_(options.image_format, options.jpeg_quality) {}

RenderLoop::~RenderLoop() = default;

void RenderLoop::run() {
  for (;;) {
    for (auto& link : hub_.take_new_links()) {
      Client client;
      client.link = std::move(link);
      if (!options_.record_path.empty() && !recording_taken_) {
        recording_taken_ = true;
        recording_.open(options_.record_path, std::ios::trunc);
        client.recorded = bool(recording_);
        log_((client.recorded ? "recording connection to " : "cannot record to ") +
             options_.record_path.string());
      }
      clients_.push_back(std::move(client));
    }
    for (Client& client : clients_) take_messages(client);
    apply_pixel_budget();
    bool rendered = false;
    const std::size_t n = clients_.size();
    for (std::size_t i = 0; i < n; ++i) rendered |= render_if_due(clients_[(next_first_ + i) % n]);
    next_first_ = n == 0 ? 0 : (next_first_ + 1) % n;
    std::erase_if(clients_, [](const Client& c) { return c.finished; });
    if (hub_.stop_requested()) break;
    // After a frame, go round again at once (a playing session wants the
    // next); otherwise sleep until a message, an ack or a connection arrives.
    if (!rendered && !hub_.wait_for_work()) break;
  }
  clients_.clear();
}

template <class Step>
void RenderLoop::guarded(Client& client, Step&& step) {
  if (client.finished) return;
  try {
    step();
  } catch (...) {
    // A failing session ends its own connection, never the server.
    log_(connection_name(client.link->id) + ": session failed: " + describe_current_exception());
    if (auto outlet = client.link->outlet.lock())
      outlet->close(close_internal_error, "session failed");
    client.finished = true;
  }
}

void RenderLoop::take_messages(Client& client) {
  ConnectionLink& link = *client.link;
  if (link.closed) {
    client.finished = true;
    return;
  }
  guarded(client, [&] {
    if (!client.session) {
      client.session = make_session_();
      if (!client.session) throw std::runtime_error("the session factory returned no session");
    }
    bool resume_reading = false;
    for (const ClientMessage& message : link.take(resume_reading)) apply(client, message);
    if (resume_reading)
      if (auto outlet = link.outlet.lock()) outlet->resume_reading();
  });
}

void RenderLoop::apply_pixel_budget() {
  double asked = 0;
  for (const Client& c : clients_)
    if (c.sized && !c.finished) asked += double(c.asked_width) * c.asked_height;
  const double budget = double(options_.pixel_budget);
  // The same factor for every view: each keeps its shape and its share.
  scale_ = budget > 0 && asked > budget ? std::sqrt(budget / asked) : 1.0;
  for (Client& c : clients_) {
    if (!c.sized) continue;
    const int width = scaled(c.asked_width, scale_);
    const int height = scaled(c.asked_height, scale_);
    if (width != c.width || height != c.height)
      guarded(c, [&] { resize_session(c, width, height); });
  }
}

bool RenderLoop::render_if_due(Client& client) {
  bool rendered = false;
  guarded(client, [&] {
    const bool room = client.link->frames_in_flight() < options_.max_frames_in_flight;
    if (client.sized && room && client.session->wants_frame()) {
      send_frame(client);
      rendered = true;
    }
    for (const Download& download : client.session->take_downloads())
      send(client, encode_file_message(download));
    for (const std::string& notice : client.session->take_notices())
      send(client, encode_notice_message(notice));
  });
  return rendered;
}

void RenderLoop::record(const Client& client, const std::string& line) {
  if (!client.recorded) return;
  recording_ << line << '\n';
  recording_.flush();  // a recording of a server stopped by a signal stays usable
}

void RenderLoop::apply(Client& client, const ClientMessage& message) {
  std::visit(
      [&](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, Resize>) {
          const int width =
              std::clamp(m.width, min_view_pixels, std::max(min_view_pixels, options_.max_width));
          const int height =
              std::clamp(m.height, min_view_pixels, std::max(min_view_pixels, options_.max_height));
          client.asked_width = width;
          client.asked_height = height;
          client.sized = true;
          // At once, in order with the input around it, at the last round's
          // scale; apply_pixel_budget then corrects every view's scale.
          resize_session(client, scaled(width, scale_), scaled(height, scale_));
        } else if constexpr (std::is_same_v<T, render::InputEvent>) {
          record(client, encode_client_message(message));
          if (m.seq != 0) client.last_seq = m.seq;
          client.session->input(m);
        }
        // Acks never reach the inbox: the network thread records them directly.
      },
      message);
}

void RenderLoop::resize_session(Client& client, int width, int height) {
  // Recorded as the session gets it (clamped, scaled), so a replay makes the same calls.
  record(client, encode_client_message(Resize{width, height}));
  client.session->resize(width, height);
  client.width = width;
  client.height = height;
}

void RenderLoop::send_frame(Client& client) {
  record(client, R"({"type":"render"})");
  const auto render_start = Clock::now();
  const render::RgbaImage& image = client.session->render();
  const double render_ms = ms_since(render_start);
  const auto encode_start = Clock::now();
  EncodedImage encoded = encoder_.encode(image);
  FrameInfo info;
  info.frame = client.link->frames_sent + 1;
  info.seq = client.last_seq;
  info.width = image.width;
  info.height = image.height;
  info.mime = encoded.mime;
  info.render_ms = render_ms;
  info.encode_ms = ms_since(encode_start);
  info.controls_json = client.session->controls_json();
  // Counted before it is handed over, so an ack can never name a frame that
  // is not yet counted as sent.
  client.link->frames_sent = info.frame;
  ++counters_.frames_sent;
  if (client.width < client.asked_width) ++counters_.downscaled_frames;
  send(client, encode_frame_message(info, encoded.bytes), info.frame);
}

void RenderLoop::send(const Client& client, std::vector<std::uint8_t> message, std::int64_t frame) {
  if (auto outlet = client.link->outlet.lock()) outlet->send(std::move(message), frame);
}

}  // namespace epviz::serve
