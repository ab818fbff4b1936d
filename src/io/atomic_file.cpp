#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <utility>

namespace epviz::io {
namespace {

std::string errno_text(int error) { return std::system_category().message(error); }

}  // namespace

std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
  std::filesystem::path temporary = target;
  temporary += ".tmp-" + std::to_string(::getpid());
  return temporary;
}

AtomicFile::AtomicFile(std::filesystem::path target, bool sync)
    : target_(std::move(target)), temporary_(temporary_path_for(target_)), sync_(sync) {
  // O_TRUNC: a temporary left by a crashed run of this pid is stale; start over.
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    const int error = errno;
    throw FileWriteError("cannot write '" + target_.string() + "': cannot create temporary '" +
                         temporary_.string() + "': " + errno_text(error));
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) discard();
}

void AtomicFile::discard() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
}

void AtomicFile::write(std::span<const std::byte> data) {
  if (fd_ < 0) throw FileWriteError("cannot write '" + target_.string() + "': file already closed");
  const auto* bytes = reinterpret_cast<const char*>(data.data());
  std::size_t left = data.size();
  while (left > 0) {
    const ssize_t written = ::write(fd_, bytes, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      discard();
      throw FileWriteError("cannot write '" + target_.string() + "': " + errno_text(error));
    }
    bytes += written;
    left -= static_cast<std::size_t>(written);
  }
}

void AtomicFile::write(std::string_view text) {
  write(std::as_bytes(std::span<const char>(text.data(), text.size())));
}

void AtomicFile::commit() {
  if (committed_) return;
  if (fd_ < 0) throw FileWriteError("cannot write '" + target_.string() + "': file already closed");
  if (sync_ && ::fsync(fd_) != 0) {
    const int error = errno;
    discard();
    throw FileWriteError("cannot write '" + target_.string() + "': fsync: " + errno_text(error));
  }
  // close() can report a deferred write error (NFS, quota): check it.
  const int closed = ::close(fd_);
  fd_ = -1;
  if (closed != 0) {
    const int error = errno;
    discard();
    throw FileWriteError("cannot write '" + target_.string() + "': close: " + errno_text(error));
  }
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
    const int error = errno;
    discard();
    throw FileWriteError("cannot write '" + target_.string() + "': rename from '" +
                         temporary_.string() + "': " + errno_text(error));
  }
  committed_ = true;
}

void write_file_atomically(const std::filesystem::path& target, std::span<const std::byte> data,
                           bool sync) {
  AtomicFile file(target, sync);
  file.write(data);
  file.commit();
}

void write_file_atomically(const std::filesystem::path& target, std::string_view text, bool sync) {
  AtomicFile file(target, sync);
  file.write(text);
  file.commit();
}

}  // namespace epviz::io
