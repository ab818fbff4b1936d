#pragma once
// Everything the network thread and the render thread share, in one place so
// that what crosses threads stays small and visibly guarded: a log, counters,
// and per connection an inbox, two frame counters and a closed flag. Sessions
// never appear here; only the render thread touches them.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "serve/protocol.hpp"
#include "serve/stage_times.hpp"

namespace epviz::serve {

// options.log, serialized: both threads log, and the sink need not be thread-safe.
class ServerLog {
 public:
  explicit ServerLog(std::function<void(const std::string&)> sink) : sink_(std::move(sink)) {}
  void operator()(const std::string& line) const {
    if (!sink_) return;
    std::lock_guard lock(mutex_);
    sink_(line);
  }

 private:
  std::function<void(const std::string&)> sink_;
  mutable std::mutex mutex_;
};

// WebSocket close codes the server sends (RFC 6455, 7.4.1), here so that code
// without Beast (the render loop) can name them.
inline constexpr std::uint16_t close_going_away = 1001;      // the server is stopping
inline constexpr std::uint16_t close_policy_error = 1008;    // a malformed message
inline constexpr std::uint16_t close_too_big = 1009;         // a message over max_message_bytes
inline constexpr std::uint16_t close_internal_error = 1011;  // the session failed

// How log lines name a connection, the same from both threads.
inline std::string connection_name(long id) { return "connection #" + std::to_string(id); }

struct ServerCounters {
  std::atomic<long> connections_accepted{0};
  std::atomic<long> connections_open{0};
  std::atomic<long> frames_sent{0};
  std::atomic<long> protocol_errors{0};
  std::atomic<long> outbox_bytes{0};       // waiting to be written, all connections together
  std::atomic<long> outbox_bytes_peak{0};  // the most outbox_bytes has been
  std::atomic<long> outbox_overflows{0};   // connections dropped for a full outbox
  std::atomic<long> downscaled_frames{0};  // rendered smaller than asked (pixel or frame budget)
  StageTimes stages;                       // each frame's stages, all connections together
};

// What `GET /stats` answers: the counters and the stages' medians (docs/serve.md).
nlohmann::json stats_json(const ServerCounters& counters);

// The network side of one connection as the render thread sees it. Every
// call may come from any thread; it only queues work for the network thread.
class ConnectionOutlet {
 public:
  virtual ~ConnectionOutlet() = default;
  // One binary WebSocket message; `frame` is its frame number, 0 for other
  // messages (a frame counts as delivered once its write has completed).
  virtual void send(std::vector<std::uint8_t> message, std::int64_t frame) = 0;
  virtual void resume_reading() = 0;  // the inbox has room again
  virtual void close(std::uint16_t code, std::string reason) = 0;
};

// One connection's state shared by both threads.
class ConnectionLink {
 public:
  // Messages waiting beyond this stop the network side reading (TCP then
  // pushes back on the page) until the render thread has drained them, so a
  // page flooding events cannot grow the server's memory without bound.
  static constexpr std::size_t inbox_limit = 1024;

  ConnectionLink(long connection_id, std::weak_ptr<ConnectionOutlet> connection_outlet)
      : id(connection_id), outlet(std::move(connection_outlet)) {}

  const long id;
  const std::weak_ptr<ConnectionOutlet> outlet;  // expired once the network side is gone
  std::atomic<std::int64_t> frames_sent{0};      // handed to the network side (render thread)
  std::atomic<std::int64_t> frames_written{0};   // whose write completed (network thread)
  std::atomic<std::int64_t> frames_acked{0};     // the page's acks (network thread)
  std::atomic<bool> closed{false};               // the network side has finished

  // Network thread: queues a resize or input event; returns false when the
  // inbox is now full and reading should pause until resume_reading().
  bool push(ClientMessage message);
  // Render thread: takes everything queued; sets `resume` when reading was paused.
  std::vector<ClientMessage> take(bool& resume);
  // Network thread: records an ack (acks never go backwards); false for an
  // ack of a frame never sent, which only a broken or hostile page sends.
  bool acknowledge(std::int64_t frame);

  // How long the newest frame whose write completed waited in the outbox
  // (queue) and took to write (send). The network thread notes it; the
  // render thread puts it in the next frame's header, since a frame's own
  // header is written before either is known.
  struct WriteTiming {
    std::int64_t frame = 0;  // 0: none written yet
    double queue_ms = 0.0;
    double send_ms = 0.0;
  };
  void note_written(const WriteTiming& timing);
  WriteTiming last_written() const;

  // The newest frame whose decoding time the page reported with its ack.
  struct PageTiming {
    std::int64_t frame = 0;  // 0: none reported yet
    double decode_ms = 0.0;
  };
  void note_decoded(const PageTiming& timing);  // network thread
  PageTiming last_decoded() const;              // render thread
  // Frames the page cannot have shown yet. An ack counts only up to the last
  // frame whose write completed: a page cannot have shown a frame still in
  // the server's outbox, and counting a forged ack would let the outbox grow.
  std::int64_t frames_in_flight() const {
    return frames_sent - std::min(frames_acked.load(), frames_written.load());
  }

 private:
  mutable std::mutex mutex_;
  std::vector<ClientMessage> inbox_;  // guarded by mutex_
  bool paused_ = false;               // guarded by mutex_
  WriteTiming last_written_;          // guarded by mutex_
  PageTiming last_decoded_;           // guarded by mutex_
};

// Where the network thread hands new connections and wake-ups to the render
// thread, which sleeps here whenever no connection has work for it.
class RenderHub {
 public:
  void add(std::shared_ptr<ConnectionLink> link);  // a new connection (wakes the render thread)
  void notify();                                   // something changed: a message, an ack, a close
  void request_stop();

  // Render thread: blocks until notify(), add() or request_stop() happened
  // since the last call (returns at once if one did), or until `until`
  // when given; false once stopping.
  bool wait_for_work(std::optional<std::chrono::steady_clock::time_point> until = {});
  bool stop_requested();
  std::vector<std::shared_ptr<ConnectionLink>> take_new_links();

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  bool dirty_ = false;  // set by any event, cleared by wait_for_work: no wake-up is lost
  bool stopping_ = false;
  std::vector<std::shared_ptr<ConnectionLink>> new_links_;
};

}  // namespace epviz::serve
