#include "io/queued_video_writer.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace epviz::io {

QueuedVideoWriter::QueuedVideoWriter(std::unique_ptr<VideoWriter> writer)
    : writer_(std::move(writer)) {
  if (!writer_) throw std::invalid_argument("QueuedVideoWriter: no writer");
  thread_ = std::thread([this] { run(); });
}

QueuedVideoWriter::~QueuedVideoWriter() { stop(); }

void QueuedVideoWriter::stop() noexcept {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void QueuedVideoWriter::rethrow_error_locked() {
  if (error_) std::rethrow_exception(error_);
}

void QueuedVideoWriter::write_frame(std::span<const std::uint8_t> rgba) {
  const std::size_t bytes = std::size_t(writer_->width()) * std::size_t(writer_->height()) * 4;
  if (rgba.size() != bytes) {
    std::string what = "video '";
    what += writer_->target().string();
    what += "': frame has ";
    what += std::to_string(rgba.size());
    what += " bytes, expected ";
    what += std::to_string(bytes);
    throw std::invalid_argument(what);
  }
  std::unique_lock lock(mutex_);
  if (stopping_) throw std::logic_error("QueuedVideoWriter::write_frame after finish()");
  changed_.wait(lock, [&] { return !full_ || error_; });
  rethrow_error_locked();
  slot_.assign(rgba.begin(), rgba.end());
  full_ = true;
  lock.unlock();
  changed_.notify_all();
}

void QueuedVideoWriter::finish() {
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return (!full_ && !busy_) || error_; });
    rethrow_error_locked();
  }
  stop();
  rethrow_error_locked();  // the thread has ended: no lock needed
  writer_->finish();
}

std::size_t QueuedVideoWriter::frames_written() const {
  std::lock_guard lock(mutex_);
  return written_;
}

void QueuedVideoWriter::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return full_ || stopping_; });
    if (stopping_) return;  // a frame still in the slot is dropped
    std::swap(slot_, writing_);
    full_ = false;
    busy_ = true;
    lock.unlock();
    changed_.notify_all();
    std::exception_ptr error;
    try {
      writer_->write_frame(writing_.data());
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    busy_ = false;
    if (error)
      error_ = error;
    else
      ++written_;
    changed_.notify_all();
    if (error) return;
  }
}

}  // namespace epviz::io
