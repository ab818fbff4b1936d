#pragma once
// A VideoWriter fed from a thread of its own, so that the caller draws the
// next frame while ffmpeg takes this one. The pipe holds 64 kB of the 3.7 MB
// of a 1280x720 frame, so a plain write_frame lasts until ffmpeg has read
// nearly all of it (3-5 ms a frame of `epviz render`'s main thread, measured
// on the 2-core machine; docs/ensembles.md, The cloud).
//
// write_frame copies the frame into a slot and returns, waiting only while
// the previous frame is still in the slot. The first error of the writing
// thread is rethrown by the next write_frame or by finish(); the frames
// after it are dropped. Frames reach ffmpeg in the order given.
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

#include "io/video_writer.hpp"

namespace epviz::io {

class QueuedVideoWriter {
 public:
  explicit QueuedVideoWriter(std::unique_ptr<VideoWriter> writer);
  // Without finish(): drops the frame in the slot and leaves no video (the
  // VideoWriter's destructor removes its temporary).
  ~QueuedVideoWriter();
  QueuedVideoWriter(const QueuedVideoWriter&) = delete;
  QueuedVideoWriter& operator=(const QueuedVideoWriter&) = delete;

  // One frame of width*height*4 bytes (std::invalid_argument otherwise).
  void write_frame(std::span<const std::uint8_t> rgba);
  // Writes the frame in the slot, then VideoWriter::finish(); rethrows the
  // writing thread's error. Idempotent after success.
  void finish();

  std::size_t frames_written() const;

 private:
  void run();
  void stop() noexcept;
  void rethrow_error_locked();

  std::unique_ptr<VideoWriter> writer_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::uint8_t> slot_;     // the next frame for the thread, when `full_`
  std::vector<std::uint8_t> writing_;  // the thread's frame
  bool full_ = false;
  bool busy_ = false;  // the thread is writing a frame
  bool stopping_ = false;
  std::size_t written_ = 0;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace epviz::io
