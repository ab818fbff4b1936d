#pragma once
// The render thread's work: the only code that creates, drives and destroys
// sessions, so a session (and the GL context behind it) is only ever touched
// from one thread. It serves the connections round-robin, at most one frame
// each per round, and sleeps in the RenderHub whenever no connection can use
// a frame. A round's pixels are bounded (ServerOptions::pixel_budget): when
// the views together ask for more, every view is rendered smaller by the same
// factor, so a round takes bounded time and every connection keeps a frame
// rate however many large views are open.
#include <chrono>
#include <cstdint>
#include <deque>
#include <fstream>
#include <memory>
#include <optional>
#include <vector>

#include "serve/image_encoder.hpp"
#include "serve/server.hpp"
#include "serve/session.hpp"
#include "serve/shared_state.hpp"

namespace epviz::serve {

class RenderLoop {
 public:
  RenderLoop(const ServerOptions& options, RenderHub& hub, SessionFactory make_session,
             const ServerLog& log, ServerCounters& counters);
  ~RenderLoop();
  RenderLoop(const RenderLoop&) = delete;
  RenderLoop& operator=(const RenderLoop&) = delete;

  // Serves until hub.request_stop(), then destroys every session (on this thread).
  void run();

 private:
  struct SentSize {
    std::int64_t frame;
    int width, height;
  };
  struct Client {
    std::shared_ptr<ConnectionLink> link;
    std::unique_ptr<Session> session;
    bool sized = false;                     // no frame before the page has said how big its view is
    int asked_width = 0, asked_height = 0;  // the page's view, clamped to the limits
    int width = 0, height = 0;              // what the session renders (within the budget)
    std::uint64_t last_seq = 0;             // of the last input event applied
    bool finished = false;                  // remove (and destroy the session) after this pass
    bool recorded = false;                  // its messages go to options.record_path
    // Adaptive resolution (ServerOptions::frame_budget_ms): the scale of each
    // side while the picture moves, and whether it was sharpened at rest.
    double detail = 1.0;
    bool resting = false;
    std::optional<std::chrono::steady_clock::time_point> idle_since;  // smaller, no frame wanted
    double cost_ms = 0.0;             // average frame cost at this detail (adapt_detail)
    int frames_at_detail = 0;         // frames averaged into cost_ms
    std::deque<SentSize> sent_sizes;  // the newest frames' sizes, oldest first
  };

  // Each step for one connection; a session that throws ends its connection only.
  void take_messages(Client& client);
  void apply_pixel_budget();
  bool render_if_due(Client& client);  // true when it rendered a frame
  template <class Step>
  void guarded(Client& client, Step&& step);
  void apply(Client& client, const ClientMessage& message);
  render::InputEvent in_session_pixels(const Client& client, render::InputEvent event) const;
  void resize_session(Client& client, int width, int height);
  void fit_view(Client& client);  // the size from the page's, the budget's scale and the detail
  void adapt_detail(Client& client, double frame_cost_ms);
  // What the page last reported for decoding a frame of the size now drawn
  // (negative: nothing reported for this size yet).
  double page_decode_at_current_size(const Client& client) const;
  // Sharpens a view that has rested long enough; true when it did.
  bool sharpen_if_rested(Client& client);
  // When the earliest view at rest is due to be sharpened, if any.
  std::optional<std::chrono::steady_clock::time_point> next_sharpening() const;
  void send_frame(Client& client);
  void send(const Client& client, std::vector<std::uint8_t> message, std::int64_t frame = 0);
  void record(const Client& client, const std::string& line);

  const ServerOptions& options_;
  RenderHub& hub_;
  SessionFactory make_session_;
  const ServerLog& log_;
  ServerCounters& counters_;
  ImageEncoder encoder_;
  std::vector<Client> clients_;
  double scale_ = 1.0;          // the pixel budget's factor for every view, from the last round
  std::size_t next_first_ = 0;  // where the next round starts: no connection is always first
  std::ofstream recording_;
  bool recording_taken_ = false;  // only the first connection is recorded
};

}  // namespace epviz::serve
