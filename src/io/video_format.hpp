#pragma once
// The video formats epviz writes through ffmpeg (io/video_writer.hpp), and
// what each asks of the frames' size.
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace epviz::io {

enum class VideoFormat { mp4, webm, gif };
inline constexpr std::array<VideoFormat, 3> video_formats = {VideoFormat::mp4, VideoFormat::webm,
                                                             VideoFormat::gif};

// "mp4", "webm", "gif".
std::string_view video_format_name(VideoFormat format);
// Parses a format name as written on the command line; nullopt if unknown.
std::optional<VideoFormat> parse_video_format(std::string_view name);
// The file extension with its dot: ".mp4", ".webm", ".gif".
std::string_view video_format_extension(VideoFormat format);
// Whether the format needs even width and height (yuv420p): mp4 and webm.
bool video_format_needs_even_size(VideoFormat format);

// Why `format` cannot hold frames of width x height (one line naming the
// format and the size, and what to do), or "" when it can. The writer and
// the commands that check a size before any work share it, so that they
// agree on which sizes each format takes.
std::string video_size_problem(VideoFormat format, int width, int height);

}  // namespace epviz::io
