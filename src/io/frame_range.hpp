#pragma once
// The `--frames` option: which frames of a job to render. Frames are numbered
// from 0 (frame i is the one written as frame_<i>.png). Both ends are
// inclusive, like Blender's -s/-e:
//   "A:B"  frames A..B      "A:"  A to the last frame
//   ":B"   0..B             "N"   only frame N
// A, B and N are non-negative decimal integers.
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "io/bad_input.hpp"

namespace epviz::io {

// Thrown for a malformed or unusable range; the message names --frames and
// says what is allowed.
class FrameRangeError : public BadInput {
 public:
  using BadInput::BadInput;
};

// What was written, before the job's frame count is known; an absent end means open.
struct FrameRangeSpec {
  std::optional<int> first;
  std::optional<int> last;
};

// Frames first..last, both inclusive.
struct FrameRange {
  int first = 0;
  int last = -1;
  int count() const { return last - first + 1; }
  bool contains(int frame) const { return frame >= first && frame <= last; }
  bool operator==(const FrameRange&) const = default;
};

// Syntax only. Throws FrameRangeError for anything but the four forms.
FrameRangeSpec parse_frame_range(std::string_view text);

// A comma-separated list of ranges ("0,5:9,20:"), syntax only; empty text:
// none. Throws FrameRangeError for an empty item or one parse_frame_range refuses.
std::vector<FrameRangeSpec> parse_frame_ranges(std::string_view text);

// Fills open ends from a job of `frame_count` frames (0..frame_count-1) and
// validates: an end past the last frame or first > last is an error (no silent
// clamping: the range asked for is not what would be rendered).
FrameRange resolve_frame_range(const FrameRangeSpec& spec, int frame_count);

// parse_frame_range then resolve_frame_range.
FrameRange parse_frame_range(std::string_view text, int frame_count);

// All frames of a job.
inline FrameRange all_frames(int frame_count) { return FrameRange{0, frame_count - 1}; }

}  // namespace epviz::io
