#pragma once
// PNG output through stb_image_write, written atomically, plus an asynchronous
// writer that encodes on a few worker threads with a bounded queue (PNG
// encoding is the slow part of a frame; the queue bound keeps memory flat no
// matter how many frames a job has).
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

namespace epviz::io {

// Encoder settings. Measured on a rendered 1280x720 frame of the synthetic
// test scene (tests/io, DISABLED_Timing; machine under load from parallel
// builds, so absolute times are high, ratios hold): stb's defaults (level 8,
// trying all five filters per row) 97 ms, 394 kB; level 1 with filter "up"
// 56 ms, 402 kB; level 1 with no filter 44 ms, 411 kB. stb's zlib speed hardly
// depends on the level; the per-row filter search is what costs. Rendered
// frames are mostly flat colour, so "none" loses only ~4 % in size.
struct PngOptions {
  int compression_level = 1;  // stb zlib level, 1 (fast) .. 9 (small)
  int filter = 0;             // PNG row filter 0..4 for every row; -1 lets stb try all per row
};

// A PNG in memory. `rgba` holds `height` top-down rows of `width` RGBA8 pixels.
std::vector<std::uint8_t> encode_png_rgba(int width, int height, std::span<const std::uint8_t> rgba,
                                          const PngOptions& options = {});

// Encodes and writes atomically; throws FileWriteError (atomic_file.hpp) or
// std::invalid_argument for a buffer that does not match the size.
void write_png_rgba(const std::filesystem::path& path, int width, int height,
                    std::span<const std::uint8_t> rgba, const PngOptions& options = {});

struct AsyncPngWriterOptions {
  int threads = 2;     // encoder threads
  int max_queued = 4;  // frames waiting to be encoded; submit() blocks beyond this
  PngOptions png;
};

// Encodes and writes frames on worker threads. submit() takes the pixels by
// value (move them in) and blocks while the queue is full. The first error a
// worker meets is rethrown by the next submit(), wait_idle() or close().
class AsyncPngWriter {
 public:
  explicit AsyncPngWriter(AsyncPngWriterOptions options = {});
  ~AsyncPngWriter();  // finishes queued frames; errors are swallowed here, call close() to see them
  AsyncPngWriter(const AsyncPngWriter&) = delete;
  AsyncPngWriter& operator=(const AsyncPngWriter&) = delete;

  void submit(std::filesystem::path path, int width, int height, std::vector<std::uint8_t> rgba);
  // Blocks until every submitted frame is on disk.
  void wait_idle();
  // Finishes the queue and stops the workers; idempotent.
  void close();

  std::size_t frames_written() const;

 private:
  struct Job {
    std::filesystem::path path;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
  };
  void worker_loop();
  void rethrow_error_locked();

  AsyncPngWriterOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable work_ready_;
  std::condition_variable space_free_;
  std::condition_variable idle_;
  std::deque<Job> queue_;
  std::vector<std::thread> workers_;
  int busy_ = 0;
  bool stopping_ = false;
  std::size_t written_ = 0;
  std::exception_ptr error_;
};

}  // namespace epviz::io
