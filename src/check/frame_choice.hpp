#pragma once
// Which frames of a job `epviz check` draws and compares.
#include <span>
#include <vector>

#include "io/frame_range.hpp"

namespace epviz::check {

// The frames of `ranges`, ends resolved against a job of `frame_count`
// frames, each once, increasing; with no ranges the first, the middle and the
// last frame. Throws io::FrameRangeError for a range outside the job.
std::vector<int> frames_to_check(std::span<const io::FrameRangeSpec> ranges, int frame_count);

}  // namespace epviz::check
