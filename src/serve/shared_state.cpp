#include "serve/shared_state.hpp"

#include <algorithm>

namespace epviz::serve {

bool ConnectionLink::push(ClientMessage message) {
  std::lock_guard lock(mutex_);
  inbox_.push_back(std::move(message));
  if (inbox_.size() >= inbox_limit) paused_ = true;
  return !paused_;
}

std::vector<ClientMessage> ConnectionLink::take(bool& resume) {
  std::vector<ClientMessage> taken;
  std::lock_guard lock(mutex_);
  taken.swap(inbox_);
  resume = paused_;
  paused_ = false;
  return taken;
}

void ConnectionLink::note_written(const WriteTiming& timing) {
  std::lock_guard lock(mutex_);
  last_written_ = timing;
}

ConnectionLink::WriteTiming ConnectionLink::last_written() const {
  std::lock_guard lock(mutex_);
  return last_written_;
}

void ConnectionLink::note_decoded(const PageTiming& timing) {
  std::lock_guard lock(mutex_);
  if (timing.frame > last_decoded_.frame) last_decoded_ = timing;
}

ConnectionLink::PageTiming ConnectionLink::last_decoded() const {
  std::lock_guard lock(mutex_);
  return last_decoded_;
}

nlohmann::json stats_json(const ServerCounters& c) {
  return {{"connections_accepted", c.connections_accepted.load()},
          {"connections_open", c.connections_open.load()},
          {"frames_sent", c.frames_sent.load()},
          {"protocol_errors", c.protocol_errors.load()},
          {"outbox_bytes", c.outbox_bytes.load()},
          {"outbox_bytes_peak", c.outbox_bytes_peak.load()},
          {"outbox_overflows", c.outbox_overflows.load()},
          {"downscaled_frames", c.downscaled_frames.load()},
          {"stages", c.stages.summary()}};
}

bool ConnectionLink::acknowledge(std::int64_t frame) {
  if (frame > frames_sent.load()) return false;
  std::int64_t current = frames_acked.load();
  // Only the network thread writes, but a CAS loop keeps this right if that changes.
  while (frame > current && !frames_acked.compare_exchange_weak(current, frame)) {
  }
  return true;
}

void RenderHub::add(std::shared_ptr<ConnectionLink> link) {
  {
    std::lock_guard lock(mutex_);
    new_links_.push_back(std::move(link));
    dirty_ = true;
  }
  wake_.notify_one();
}

void RenderHub::notify() {
  {
    std::lock_guard lock(mutex_);
    dirty_ = true;
  }
  wake_.notify_one();
}

void RenderHub::request_stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
}

bool RenderHub::wait_for_work(std::optional<std::chrono::steady_clock::time_point> until) {
  std::unique_lock lock(mutex_);
  const auto woken = [&] { return dirty_ || stopping_; };
  if (until)
    wake_.wait_until(lock, *until, woken);
  else
    wake_.wait(lock, woken);
  dirty_ = false;
  return !stopping_;
}

bool RenderHub::stop_requested() {
  std::lock_guard lock(mutex_);
  return stopping_;
}

std::vector<std::shared_ptr<ConnectionLink>> RenderHub::take_new_links() {
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<ConnectionLink>> taken;
  taken.swap(new_links_);
  return taken;
}

}  // namespace epviz::serve
