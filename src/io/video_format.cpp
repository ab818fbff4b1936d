#include "io/video_format.hpp"

namespace epviz::io {

std::string_view video_format_name(VideoFormat format) {
  switch (format) {
    case VideoFormat::mp4: return "mp4";
    case VideoFormat::webm: return "webm";
    case VideoFormat::gif: return "gif";
  }
  return "?";
}

std::optional<VideoFormat> parse_video_format(std::string_view name) {
  for (auto f : video_formats)
    if (video_format_name(f) == name) return f;
  return std::nullopt;
}

std::string_view video_format_extension(VideoFormat format) {
  switch (format) {
    case VideoFormat::mp4: return ".mp4";
    case VideoFormat::webm: return ".webm";
    case VideoFormat::gif: return ".gif";
  }
  return "";
}

bool video_format_needs_even_size(VideoFormat format) { return format != VideoFormat::gif; }

std::string video_size_problem(VideoFormat format, int width, int height) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width <= 0 || height <= 0) return "size " + size + " must be positive";
  if (video_format_needs_even_size(format) && (width % 2 != 0 || height % 2 != 0))
    return std::string(video_format_name(format)) +
           " (yuv420p) needs an even width and height, got " + size +
           "; choose even --width/--height or use --format gif or png";
  return "";
}

}  // namespace epviz::io
