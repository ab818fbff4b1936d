#pragma once
// Atomic file writes: the data goes to "<name>.tmp-<pid>" in the target's
// directory and is renamed over the target only once it is complete, so a
// reader (or a later `--resume`) never sees a partial file under the real name.
#include <cstddef>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace epviz::io {

// Thrown for any failure to write; the message names the file and the cause.
class FileWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The temporary name used while `target` is being written: "<target>.tmp-<pid>".
// It lives in the same directory so that the final rename stays on one file system.
std::filesystem::path temporary_path_for(const std::filesystem::path& target);

// An open temporary file that becomes `target` on commit(). If it is destroyed
// without commit() (an exception, an early return) the temporary is removed.
// Not for two writers of the same target in one process at the same time.
class AtomicFile {
 public:
  // `sync`: fsync before the rename, for durability across power loss. Off by
  // default: atomic visibility needs only the rename, and fsync per frame is slow.
  explicit AtomicFile(std::filesystem::path target, bool sync = false);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::span<const std::byte> data);
  void write(std::string_view text);
  // Closes the temporary and renames it over the target.
  void commit();

  const std::filesystem::path& target() const { return target_; }

 private:
  void discard() noexcept;

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  int fd_ = -1;
  bool sync_ = false;
  bool committed_ = false;
};

// Writes a whole buffer to `target` atomically.
void write_file_atomically(const std::filesystem::path& target, std::span<const std::byte> data,
                           bool sync = false);
void write_file_atomically(const std::filesystem::path& target, std::string_view text,
                           bool sync = false);

}  // namespace epviz::io
