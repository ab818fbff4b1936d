#pragma once
// Video output by piping raw RGBA frames to an ffmpeg child process
// (`ffmpeg -f rawvideo -pix_fmt rgba -s WxH -r FPS -i - ...`, as matplotlib's
// FFMpegWriter does), started through io/subprocess.hpp (no shell, so any path works).
//
// ffmpeg writes to atomic_file.hpp's temporary name for the target in
// the target's directory; finish() waits for ffmpeg and renames the temporary
// over the target only if ffmpeg succeeded. A failed run, an exception or a
// destructor without finish() kills ffmpeg and removes the temporary, so the
// real name never holds a partial video. On SIGINT/SIGTERM ffmpeg is killed and
// the temporary removed (io/temp_registry.hpp).
//
// Sizes: mp4 and webm are encoded as yuv420p, which needs even width and
// height; an odd size is rejected up front (std::invalid_argument naming the
// size and the format) rather than padded, so the video always has exactly the
// size asked for. gif takes any size.
//
// Encoder settings. Measured at 1280x720, 300 frames, 60 fps, on the 2-core
// build machine through this class (tests/io/video_writer_test.cpp,
// DISABLED_Throughput: a flat background with a moving disc and a moving
// gradient band, like a rendered frame), end to end frames/s / ffmpeg CPU per
// frame / file size:
//   mp4  x264 ultrafast  196 fps  5.0 ms  209 kB
//   mp4  x264 superfast  151 fps  7.1 ms  160 kB   <- chosen
//   mp4  x264 veryfast   147 fps  9.3 ms  152 kB
//   webm vp9 realtime    138 fps  7.8 ms  382 kB
//   gif  palette         37 fps  24 ms  11.4 MB
// On a busy synthetic picture (ffmpeg testsrc2, 240 frames) x264 ultrafast /
// superfast / veryfast ran at >=187 / 153 / 118 fps with 6.1 / 3.6 / 1.6 MB;
// -tune animation was slower and larger there; vp8 (libvpx, realtime) was far
// slower (17 fps) than vp9 realtime (85 fps). superfast keeps x264 to ~7 ms of
// CPU per frame, leaving the renderer most of the 2 cores for the >= 60 fps
// MP4 target, at 25-40 % less size than ultrafast.
//   mp4:  libx264 -preset superfast -crf 23 -pix_fmt yuv420p -movflags +faststart
//   webm: libvpx-vp9 -deadline realtime -cpu-used 8 -row-mt 1 -b:v 0 -crf 35 -pix_fmt yuv420p
//   gif:  split -> palettegen (stats_mode=diff) -> paletteuse (bayer dither), -loop 0.
//         palettegen sees the whole clip before the first frame is written, so
//         ffmpeg holds every frame in memory: meant for short clips.
// ffmpeg runs with -nostdin -loglevel error; its stderr goes to an unlinked
// temporary file and is quoted in the exception when it fails.
//
// SIGPIPE: a write to an ffmpeg that has died raises no signal (Subprocess's
// writes block and consume it); the write reports the failure with ffmpeg's stderr.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "io/subprocess.hpp"
#include "io/video_format.hpp"

namespace epviz::io {

// Thrown when ffmpeg is missing, cannot be started, or fails; the message names
// the output file and, when ffmpeg itself failed, quotes its stderr.
class VideoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct VideoOptions {
  std::string ffmpeg = "ffmpeg";  // program name (searched on PATH) or a path
  int crf = -1;                   // quality; -1: the format's default (x264 23, vp9 35)
  std::string x264_preset = "superfast";
};

// Whether `program` (default "ffmpeg") can be found on PATH and executed.
// A name with a '/' is checked as a path.
bool ffmpeg_available(const std::string& program = "ffmpeg");

// The full argument list (argv[0] = options.ffmpeg) used to encode to `output`.
std::vector<std::string> ffmpeg_arguments(VideoFormat format, int width, int height, double fps,
                                          const std::filesystem::path& output,
                                          const VideoOptions& options = {});

class VideoWriter {
 public:
  // Starts ffmpeg. Throws std::invalid_argument for a non-positive or (mp4,
  // webm) odd size or a non-positive fps, VideoError if the target's directory
  // does not exist or is not writable, or if ffmpeg is not found on PATH
  // ("ffmpeg not found on PATH: install the Debian package ffmpeg
  // (scripts/setup.sh does)") or cannot be started.
  VideoWriter(std::filesystem::path target, VideoFormat format, int width, int height, double fps,
              VideoOptions options = {});
  // Without a successful finish(): kills ffmpeg and removes the temporary.
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // One frame of height top-down rows of width RGBA8 pixels (width*height*4
  // bytes). Blocks while ffmpeg is busy. Throws VideoError (with ffmpeg's
  // stderr) if ffmpeg has exited; the temporary is then removed.
  void write_frame(const std::uint8_t* rgba);
  // The same with a size check (std::invalid_argument if the size is wrong).
  void write_frame(std::span<const std::uint8_t> rgba);

  // Closes ffmpeg's input, waits for it, and renames the temporary over the
  // target. Throws VideoError if no frame was written or ffmpeg failed (then
  // nothing is left under either name). Idempotent after success.
  void finish();

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporary() const { return temporary_; }
  VideoFormat format() const { return format_; }
  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t frames_written() const { return frames_; }

 private:
  void abort() noexcept;                // kill, reap, remove the temporary
  ExitStatus wait_for_exit() noexcept;  // closes ffmpeg's input and reaps it
  std::string ffmpeg_stderr() const;
  [[noreturn]] void fail(const std::string& what);

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  VideoFormat format_;
  int width_ = 0;
  int height_ = 0;
  std::size_t frame_bytes_ = 0;
  std::size_t frames_ = 0;
  std::unique_ptr<Subprocess> ffmpeg_;  // null once reaped
  int stderr_fd_ = -1;                  // unlinked temporary holding ffmpeg's stderr
  int cleanup_slot_ = -1;               // the temporary and ffmpeg in temp_registry.hpp
  bool finished_ = false;
};

}  // namespace epviz::io
