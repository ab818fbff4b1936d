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

// Adaptive resolution changes the detail in steps of this (fewer sizes, fewer reallocations).
constexpr double detail_step = 1.0 / 16.0;
// Frames averaged (a plain mean) before the detail is judged again.
constexpr int frames_to_judge = 4;
// Below this share of the budget a frame is cheap enough to add detail.
constexpr double cheap_share = 0.5;
// Sizes of the newest frames sent, enough to cover every frame in flight.
constexpr std::size_t sent_sizes_kept = 16;

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
    if (!rendered && !hub_.wait_for_work(next_sharpening())) break;
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
  for (Client& c : clients_)
    if (c.sized) guarded(c, [&] { fit_view(c); });
}

void RenderLoop::fit_view(Client& client) {
  const double scale = scale_ * (client.resting ? 1.0 : client.detail);
  const int width = scaled(client.asked_width, scale);
  const int height = scaled(client.asked_height, scale);
  if (width != client.width || height != client.height) resize_session(client, width, height);
}

bool RenderLoop::sharpen_if_rested(Client& client) {
  if (client.resting || client.detail >= 1.0 || client.session->wants_frame()) {
    client.idle_since.reset();
    return false;
  }
  const auto now = Clock::now();
  if (!client.idle_since) client.idle_since = now;
  if (now - *client.idle_since < options_.rest_before_sharpening) return false;
  // Once more at full size: the resize makes the session want that frame.
  client.idle_since.reset();
  client.resting = true;
  fit_view(client);
  return true;
}

std::optional<Clock::time_point> RenderLoop::next_sharpening() const {
  std::optional<Clock::time_point> first;
  for (const Client& c : clients_)
    if (c.idle_since && !c.finished) {
      const Clock::time_point due = *c.idle_since + options_.rest_before_sharpening;
      if (!first || due < *first) first = due;
    }
  return first;
}

void RenderLoop::adapt_detail(Client& client, double frame_cost_ms) {
  const double budget = options_.frame_budget_ms;
  if (budget <= 0 || client.resting) return;
  ++client.frames_at_detail;
  client.cost_ms += (frame_cost_ms - client.cost_ms) / double(client.frames_at_detail);
  if (client.frames_at_detail < frames_to_judge) return;
  double detail = client.detail;
  const double min_detail = std::clamp(options_.min_detail, detail_step, 1.0);
  if (client.cost_ms > budget && detail > min_detail) {
    // Cost goes roughly with the pixels, the square of the detail; at least one step down.
    const double aim = detail * std::sqrt(budget / client.cost_ms);
    detail = std::max(min_detail,
                      std::min(detail - detail_step, std::floor(aim / detail_step) * detail_step));
  } else if (client.cost_ms < cheap_share * budget && detail < 1.0) {
    detail = std::min(1.0, detail + detail_step);
  }
  client.cost_ms = 0;
  client.frames_at_detail = 0;
  if (detail == client.detail) return;
  client.detail = detail;
  fit_view(client);
}

bool RenderLoop::render_if_due(Client& client) {
  bool rendered = false;
  guarded(client, [&] {
    const bool room = client.link->frames_in_flight() < options_.max_frames_in_flight;
    if (client.sized && room) sharpen_if_rested(client);
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
          fit_view(client);
        } else if constexpr (std::is_same_v<T, render::InputEvent>) {
          if (client.resting) {
            // Moving again: back to the detail the motion had.
            client.resting = false;
            fit_view(client);
          }
          // Recorded as the session gets it, so a replay makes the same calls.
          const render::InputEvent event = in_session_pixels(client, m);
          record(client, encode_client_message(event));
          if (m.seq != 0) client.last_seq = m.seq;
          client.session->input(event);
        }
        // Acks never reach the inbox: the network thread records them directly.
      },
      message);
}

render::InputEvent RenderLoop::in_session_pixels(const Client& client,
                                                 render::InputEvent event) const {
  // The page gives positions in the pixels of the frame it shows, the last
  // one it acknowledged (its ack goes out before any later event): when the
  // session has been resized since, they are scaled to its size.
  const std::int64_t shown = client.link->frames_acked;
  const auto it = std::find_if(client.sent_sizes.rbegin(), client.sent_sizes.rend(),
                               [&](const SentSize& s) { return s.frame <= shown; });
  if (it == client.sent_sizes.rend() || (it->width == client.width && it->height == client.height))
    return event;
  event.x *= float(client.width) / float(it->width);
  event.y *= float(client.height) / float(it->height);
  return event;
}

void RenderLoop::resize_session(Client& client, int width, int height) {
  // Recorded as the session gets it (clamped, scaled), so a replay makes the same calls.
  record(client, encode_client_message(Resize{width, height}));
  client.session->set_view_scale(double(height) / double(std::max(1, client.asked_height)));
  client.session->resize(width, height);
  client.width = width;
  client.height = height;
}

void RenderLoop::send_frame(Client& client) {
  record(client, R"({"type":"render"})");
  const auto render_start = Clock::now();
  const render::RgbaImage& image = client.session->render();
  const double render_ms = ms_since(render_start);
  RenderStages stages = client.session->last_render_stages();
  if (stages.simulate_ms + stages.draw_ms + stages.read_back_ms <= 0) stages.draw_ms = render_ms;
  const auto encode_start = Clock::now();
  EncodedImage encoded = encoder_.encode(image);
  FrameInfo info;
  info.frame = client.link->frames_sent + 1;
  info.seq = client.last_seq;
  info.width = image.width;
  info.height = image.height;
  info.mime = encoded.mime;
  info.render_ms = render_ms;
  info.stages = stages;
  info.encode_ms = ms_since(encode_start);
  const ConnectionLink::WriteTiming written = client.link->last_written();
  info.written_frame = written.frame;
  info.queue_ms = written.queue_ms;
  info.send_ms = written.send_ms;
  info.controls_json = client.session->controls_json();
  const double server_ms = render_ms + info.encode_ms;
  const double page_ms = page_decode_at_current_size(client);
  info.adaptive = {options_.frame_budget_ms, client.detail, client.resting, server_ms, page_ms};
  StageTimes& times = counters_.stages;
  times.record(Stage::simulate, stages.simulate_ms);
  times.record(Stage::draw, stages.draw_ms);
  times.record(Stage::read_back, stages.read_back_ms);
  times.record(Stage::encode, info.encode_ms);
  // Counted before it is handed over, so an ack can never name a frame that
  // is not yet counted as sent.
  client.link->frames_sent = info.frame;
  client.sent_sizes.push_back({info.frame, image.width, image.height});
  if (client.sent_sizes.size() > sent_sizes_kept) client.sent_sizes.pop_front();
  ++counters_.frames_sent;
  if (client.width < client.asked_width) ++counters_.downscaled_frames;
  send(client, encode_frame_message(info, encoded.bytes), info.frame);
  // Frames are drawn here while the page decodes the one before, so the
  // slower of the two sets the rate.
  adapt_detail(client, std::max(server_ms, page_ms));
}

double RenderLoop::page_decode_at_current_size(const Client& client) const {
  const ConnectionLink::PageTiming timing = client.link->last_decoded();
  for (auto it = client.sent_sizes.rbegin(); it != client.sent_sizes.rend(); ++it)
    if (it->frame == timing.frame)
      return it->width == client.width && it->height == client.height ? timing.decode_ms : -1.0;
  return -1.0;  // none reported, or of a frame older than those kept
}

void RenderLoop::send(const Client& client, std::vector<std::uint8_t> message, std::int64_t frame) {
  if (auto outlet = client.link->outlet.lock()) outlet->send(std::move(message), frame);
}

}  // namespace epviz::serve
