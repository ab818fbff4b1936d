#include "check/frame_choice.hpp"

#include <set>

namespace epviz::check {

std::vector<int> frames_to_check(std::span<const io::FrameRangeSpec> ranges, int frame_count) {
  std::set<int> frames;
  if (ranges.empty()) frames = {0, (frame_count - 1) / 2, frame_count - 1};
  for (const auto& spec : ranges) {
    const auto r = io::resolve_frame_range(spec, frame_count);
    for (int i = r.first; i <= r.last; ++i) frames.insert(i);
  }
  return {frames.begin(), frames.end()};
}

}  // namespace epviz::check
