#pragma once
// Atomic file writes: the data goes to a temporary (temp_name.hpp) in the target's
// directory and is renamed over the target only once it is complete, so a
// reader (or a later `--resume`) never sees a partial file under the real name.
//
// Only regular files are replaced that way. A target that exists and is not a
// regular file (/dev/null, /dev/stdout, a FIFO, a terminal) is a stream: it is
// opened and written directly, never replaced (renaming over /dev/null would
// replace the device node). A symbolic link is followed: the file it points to
// is replaced atomically, with the temporary beside that file, and the link
// stays. "-" means standard output.
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

// The temporary name used while `target` is being written:
// "<target>.epviz-tmp-<machine>-<pid>" (temp_name.hpp).
// It lives in the same directory so that the final rename stays on one file system.
std::filesystem::path temporary_path_for(const std::filesystem::path& target);

// How a target is written, decided from what is on disk now.
enum class OutputKind {
  replace,          // a regular file or nothing yet: temporary + rename over `path`
  stream,           // an existing non-regular file: opened and written directly
  standard_output,  // "-": file descriptor 1
};

struct OutputTarget {
  OutputKind kind = OutputKind::replace;
  std::filesystem::path path;  // the file written or replaced, symbolic links followed
};

// Follows symbolic links (a dangling link: its final target, which is created).
// Throws FileWriteError for a link loop.
OutputTarget resolve_output(const std::filesystem::path& target);

// Whether writing `target` writes what this process's standard output shows:
// "-", /dev/stdout, or any path to the same file as file descriptor 1. A
// command that writes data there prints its messages to stderr instead.
bool writes_to_standard_output(const std::filesystem::path& target);

// Removes the temporaries that killed runs left beside the output `target`
// (remove_stale_temporaries in its directory, links followed as the writer
// follows them). "-", "" and streams have none. A command calls it for each
// output before writing, so that a run killed with SIGKILL leaves nothing
// for good; SIGINT and SIGTERM remove the temporaries at once (temp_registry.hpp).
void remove_stale_temporaries_beside(const std::filesystem::path& target);

// An open temporary file that becomes `target` on commit(). If it is destroyed
// without commit() (an exception, an early return) the temporary is removed.
// For a stream target (see resolve_output) the target itself is written and
// commit() only closes it; what was written cannot be taken back.
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
  OutputKind kind() const { return resolved_.kind; }

 private:
  void discard() noexcept;
  [[noreturn]] void fail(const std::string& what, int error);

  std::filesystem::path target_;
  OutputTarget resolved_;
  std::filesystem::path temporary_;  // empty for streams
  int fd_ = -1;
  int cleanup_slot_ = -1;  // temp_registry.hpp
  bool sync_ = false;
  bool committed_ = false;
};

// Writes a whole buffer to `target` atomically.
void write_file_atomically(const std::filesystem::path& target, std::span<const std::byte> data,
                           bool sync = false);
void write_file_atomically(const std::filesystem::path& target, std::string_view text,
                           bool sync = false);

}  // namespace epviz::io
