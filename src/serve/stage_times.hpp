#pragma once
// Where a live frame's time goes, stage by stage: what the render thread
// measures (simulate, draw, read back, encode) and what the network thread
// measures (queue: waiting in the outbox; send: the socket write), kept for
// the last frames of every connection so that `GET /stats` can report
// medians. Both threads record, so the samples sit behind a mutex.
#include <array>
#include <cstddef>
#include <mutex>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace epviz::serve {

enum class Stage { simulate, draw, read_back, encode, queue, send };
inline constexpr std::size_t stage_count = 6;
// The names the frame header and the stats use ("simulate_ms", ... there).
std::string_view stage_name(Stage stage);

class StageTimes {
 public:
  // Samples kept per stage (the newest): about ten seconds of frames.
  static constexpr std::size_t window = 600;

  void record(Stage stage, double ms);
  // {"<stage>": {"median_ms", "p90_ms", "samples"}, ...} over the window;
  // a stage with no sample yet has "samples": 0 and no figures.
  nlohmann::json summary() const;

 private:
  struct Ring {
    std::vector<double> samples;  // up to `window`, oldest overwritten first
    std::size_t next = 0;
  };
  mutable std::mutex mutex_;
  std::array<Ring, stage_count> rings_;  // guarded by mutex_
};

}  // namespace epviz::serve
