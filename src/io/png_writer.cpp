#include "io/png_writer.hpp"

#include "io/stb_png_zlib.hpp"

#include <shared_mutex>
#include <stdexcept>
#include <string>

#include "io/atomic_file.hpp"

namespace epviz::io {
namespace {

// stb_image_write takes its compression level and filter from two global
// variables. Encoders hold the lock shared while they run; changing a setting
// takes it exclusively, so encodes with different settings never race.
std::shared_mutex& stb_settings_mutex() {
  static std::shared_mutex mutex;
  return mutex;
}

void check_size(int width, int height, std::size_t bytes) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("PNG size must be positive, got " + std::to_string(width) + "x" +
                                std::to_string(height));
  const std::size_t expected =
      static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
  if (bytes != expected)
    throw std::invalid_argument("PNG buffer holds " + std::to_string(bytes) + " bytes, " +
                                std::to_string(width) + "x" + std::to_string(height) +
                                " RGBA needs " + std::to_string(expected));
}

// stb hands the finished PNG to this callback (in one piece, but don't rely on it).
void append_to_vector(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* begin = static_cast<const std::uint8_t*>(data);
  bytes->insert(bytes->end(), begin, begin + size);
}

}  // namespace

std::vector<std::uint8_t> encode_png_rgba(int width, int height, std::span<const std::uint8_t> rgba,
                                          const PngOptions& options) {
  check_size(width, height, rgba.size());
  if (options.compression_level < 0 || options.compression_level > 9)
    throw std::invalid_argument("PNG compression level must be 0..9");
  if (options.filter < -1 || options.filter > 4)
    throw std::invalid_argument("PNG filter must be -1 (adaptive) or 0..4");

  auto& mutex = stb_settings_mutex();
  std::vector<std::uint8_t> bytes;
  bytes.reserve(rgba.size() / 4);  // rendered frames usually compress well below this
  int ok = 0;
  for (;;) {
    {
      std::shared_lock lock(mutex);
      if (detail::png_compression_level() == options.compression_level &&
          detail::png_force_filter() == options.filter) {
        ok = detail::png_to_func(append_to_vector, &bytes, width, height, rgba.data(), width * 4);
        break;
      }
    }
    std::unique_lock exclusive(mutex);
    detail::png_compression_level() = options.compression_level;
    detail::png_force_filter() = options.filter;
  }
  if (ok == 0) throw std::runtime_error("PNG encoding failed (out of memory?)");
  return bytes;
}

void write_png_rgba(const std::filesystem::path& path, int width, int height,
                    std::span<const std::uint8_t> rgba, const PngOptions& options) {
  const auto png = encode_png_rgba(width, height, rgba, options);
  write_file_atomically(path, std::as_bytes(std::span<const std::uint8_t>(png)));
}

AsyncPngWriter::AsyncPngWriter(AsyncPngWriterOptions options) : options_(options) {
  if (options_.threads < 1) options_.threads = 1;
  if (options_.max_queued < 1) options_.max_queued = 1;
  workers_.reserve(static_cast<std::size_t>(options_.threads));
  for (int i = 0; i < options_.threads; ++i) workers_.emplace_back([this] { worker_loop(); });
}

AsyncPngWriter::~AsyncPngWriter() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw; callers who care call close() themselves.
  }
}

void AsyncPngWriter::rethrow_error_locked() {
  if (error_) {
    auto error = error_;
    error_ = nullptr;  // report once
    std::rethrow_exception(error);
  }
}

void AsyncPngWriter::submit(std::filesystem::path path, int width, int height,
                            std::vector<std::uint8_t> rgba) {
  check_size(width, height, rgba.size());
  std::unique_lock lock(mutex_);
  if (stopping_) throw std::logic_error("AsyncPngWriter::submit after close()");
  space_free_.wait(lock, [&] {
    return static_cast<int>(queue_.size()) < options_.max_queued || error_ != nullptr;
  });
  rethrow_error_locked();
  queue_.push_back(Job{std::move(path), width, height, std::move(rgba)});
  work_ready_.notify_one();
}

void AsyncPngWriter::wait_idle() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [&] { return queue_.empty() && busy_ == 0; });
  rethrow_error_locked();
}

void AsyncPngWriter::close() {
  {
    std::unique_lock lock(mutex_);
    if (!stopping_) {
      idle_.wait(lock, [&] { return queue_.empty() && busy_ == 0; });
      stopping_ = true;
    }
    work_ready_.notify_all();
  }
  for (auto& worker : workers_)
    if (worker.joinable()) worker.join();
  std::unique_lock lock(mutex_);
  rethrow_error_locked();
}

std::size_t AsyncPngWriter::frames_written() const {
  std::lock_guard lock(mutex_);
  return written_;
}

void AsyncPngWriter::worker_loop() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      work_ready_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping and nothing left
      job = std::move(queue_.front());
      queue_.pop_front();
      ++busy_;
      space_free_.notify_one();
    }
    std::exception_ptr error;
    try {
      write_png_rgba(job.path, job.width, job.height, job.rgba, options_.png);
    } catch (...) {
      error = std::current_exception();
    }
    job.rgba = {};  // free the frame before waking the producer
    std::lock_guard lock(mutex_);
    --busy_;
    if (error) {
      if (!error_) error_ = error;
      space_free_.notify_all();
    } else {
      ++written_;
    }
    if (queue_.empty() && busy_ == 0) idle_.notify_all();
  }
}

}  // namespace epviz::io
