#include "io/frame_range.hpp"

#include <charconv>
#include <string>

namespace epviz::io {
namespace {

constexpr std::string_view kAllowed =
    "allowed: A:B (frames A to B, both included), A: (from A to the last frame), :B (from the "
    "first frame "
    "to B), N (frame N alone); frames are numbered from 0";

[[noreturn]] void fail(std::string_view text, const std::string& why) {
  throw FrameRangeError("--frames '" + std::string(text) + "': " + why + "; " +
                        std::string(kAllowed));
}

int parse_index(std::string_view whole, std::string_view part, const char* which) {
  if (part.empty()) fail(whole, std::string("missing ") + which);
  for (char c : part)
    if (c < '0' || c > '9')
      fail(whole,
           std::string(which) + " '" + std::string(part) + "' is not a non-negative integer");
  int value = 0;
  const auto result = std::from_chars(part.data(), part.data() + part.size(), value);
  if (result.ec != std::errc() || result.ptr != part.data() + part.size())
    fail(whole, std::string(which) + " '" + std::string(part) + "' is too large");
  return value;
}

}  // namespace

FrameRangeSpec parse_frame_range(std::string_view text) {
  if (text.empty()) fail(text, "empty value");
  const std::size_t colon = text.find(':');
  FrameRangeSpec spec;
  if (colon == std::string_view::npos) {
    const int n = parse_index(text, text, "frame number");
    spec.first = n;
    spec.last = n;
    return spec;
  }
  if (text.find(':', colon + 1) != std::string_view::npos) fail(text, "more than one ':'");
  const std::string_view a = text.substr(0, colon);
  const std::string_view b = text.substr(colon + 1);
  if (a.empty() && b.empty()) fail(text, "neither first nor last frame given");
  if (!a.empty()) spec.first = parse_index(text, a, "first frame");
  if (!b.empty()) spec.last = parse_index(text, b, "last frame");
  if (spec.first && spec.last && *spec.first > *spec.last)
    fail(text, "first frame " + std::to_string(*spec.first) + " is after last frame " +
                   std::to_string(*spec.last) + " (the range would be empty)");
  return spec;
}

FrameRange resolve_frame_range(const FrameRangeSpec& spec, int frame_count) {
  // The range as it would have been written, for messages.
  std::string shown;
  if (spec.first) shown.append(std::to_string(*spec.first));
  if (!(spec.first && spec.last && *spec.first == *spec.last)) {
    shown.push_back(':');
    if (spec.last) shown.append(std::to_string(*spec.last));
  }
  if (frame_count < 1) throw FrameRangeError("--frames '" + shown + "': the job has no frames");
  const int last_frame = frame_count - 1;
  FrameRange range{spec.first.value_or(0), spec.last.value_or(last_frame)};
  const std::string bounds = "the job has " + std::to_string(frame_count) +
                             " frames, numbered 0 to " + std::to_string(last_frame);
  if (range.first > last_frame)
    throw FrameRangeError("--frames '" + shown + "': frame " + std::to_string(range.first) +
                          " is out of range: " + bounds);
  if (range.last > last_frame)
    throw FrameRangeError("--frames '" + shown + "': frame " + std::to_string(range.last) +
                          " is out of range: " + bounds);
  if (range.first > range.last)
    throw FrameRangeError("--frames '" + shown + "': the range is empty (first frame " +
                          std::to_string(range.first) + " is after last frame " +
                          std::to_string(range.last) + ")");
  return range;
}

FrameRange parse_frame_range(std::string_view text, int frame_count) {
  return resolve_frame_range(parse_frame_range(text), frame_count);
}

std::vector<FrameRangeSpec> parse_frame_ranges(std::string_view text) {
  std::vector<FrameRangeSpec> specs;
  if (text.empty()) return specs;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const auto item = text.substr(start, comma == std::string_view::npos ? comma : comma - start);
    if (item.empty())
      throw FrameRangeError("--frames: empty item in '" + std::string(text) +
                            "' (allowed: N, A:B, A:, :B separated by commas)");
    specs.push_back(parse_frame_range(item));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return specs;
}

}  // namespace epviz::io
