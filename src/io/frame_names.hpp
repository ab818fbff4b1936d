#pragma once
// Frame file names of PNG sequences and the completeness check behind `--resume`.
#include <filesystem>
#include <string>
#include <string_view>

namespace epviz::io {

// Digits in frame numbers of a job with `frame_count` frames (numbered 0 to
// frame_count - 1): max(4, digits of the last index), so names sort correctly.
int frame_number_width(int frame_count);

// "<prefix><index zero-padded to frame_number_width(frame_count)><extension>",
// e.g. frame_file_name(42, 100) == "frame_0042.png",
//      frame_file_name(42, 100001) == "frame_000042.png".
// Throws std::invalid_argument unless 0 <= index < frame_count.
std::string frame_file_name(int index, int frame_count, std::string_view prefix = "frame_",
                            std::string_view extension = ".png");

// For `--resume`: true if `path` is a regular file holding a complete PNG: the
// 8-byte signature, IHDR first, every chunk's CRC right, and the IEND chunk
// ending the file exactly. Frames are written atomically, so a file under its
// final name is complete unless it was damaged afterwards; this catches
// truncation and garbage without decoding. False (never an exception) for a
// missing, unreadable, truncated or corrupt file.
bool png_frame_complete(const std::filesystem::path& path);

}  // namespace epviz::io
