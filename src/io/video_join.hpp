#pragma once
// Joins video segments of one format into one file with ffmpeg's concat
// demuxer, without re-encoding: each segment starts with a key frame, so the
// stream copy is exact (the segments of a sharded render, `epviz merge`).
#include <filesystem>
#include <vector>

namespace epviz::io {

// Writes `out` from `segments` in order: through a temporary in out's
// directory, renamed only when ffmpeg succeeded. Throws VideoError
// (video_writer.hpp) with ffmpeg's message when it fails.
void join_video_segments(const std::vector<std::filesystem::path>& segments,
                         const std::filesystem::path& out);

}  // namespace epviz::io
