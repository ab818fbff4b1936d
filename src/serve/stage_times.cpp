#include "serve/stage_times.hpp"

#include <algorithm>
#include <cmath>

namespace epviz::serve {
namespace {

// The q-quantile of sorted samples, nearest rank (as tests/e2e/measure.mjs).
double quantile(const std::vector<double>& sorted, double q) {
  const auto n = sorted.size();
  const auto rank = std::size_t(std::ceil(q * double(n)));
  return sorted[std::clamp<std::size_t>(rank, 1, n) - 1];
}

}  // namespace

std::string_view stage_name(Stage stage) {
  switch (stage) {
    case Stage::simulate: return "simulate";
    case Stage::draw: return "draw";
    case Stage::read_back: return "read_back";
    case Stage::encode: return "encode";
    case Stage::queue: return "queue";
    case Stage::send: return "send";
  }
  return "unknown";
}

void StageTimes::record(Stage stage, double ms) {
  std::lock_guard lock(mutex_);
  Ring& ring = rings_[std::size_t(stage)];
  if (ring.samples.size() < window) {
    ring.samples.push_back(ms);
  } else {
    ring.samples[ring.next] = ms;
    ring.next = (ring.next + 1) % window;
  }
}

nlohmann::json StageTimes::summary() const {
  std::array<std::vector<double>, stage_count> copies;
  {
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < stage_count; ++i) copies[i] = rings_[i].samples;
  }
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < stage_count; ++i) {
    std::vector<double>& s = copies[i];
    nlohmann::json entry = {{"samples", s.size()}};
    if (!s.empty()) {
      std::sort(s.begin(), s.end());
      entry["median_ms"] = quantile(s, 0.5);
      entry["p90_ms"] = quantile(s, 0.9);
    }
    out[std::string(stage_name(Stage(i)))] = std::move(entry);
  }
  return out;
}

}  // namespace epviz::serve
