#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <utility>

#include "io/errno_text.hpp"
#include "io/temp_name.hpp"
#include "io/temp_registry.hpp"

namespace epviz::io {
namespace {

namespace fs = std::filesystem;

// A regular file (symbolic links followed) or nothing: a target to replace.
bool is_regular_or_missing(const fs::path& p) {
  struct stat st {};
  if (::stat(p.c_str(), &st) != 0) return errno == ENOENT;
  return S_ISREG(st.st_mode);
}

}  // namespace

std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
  std::filesystem::path temporary = target;
  temporary += temporary_suffix(::getpid());
  return temporary;
}

OutputTarget resolve_output(const fs::path& target) {
  if (target == "-") return {OutputKind::standard_output, target};
  fs::path p = target;
  for (int hops = 0;; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) break;
    if (hops == 40)
      throw FileWriteError("cannot write '" + target.string() + "': too many symbolic links");
    std::error_code ec;
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) throw FileWriteError("cannot write '" + target.string() + "': " + ec.message());
    // /dev/stdout -> /proc/self/fd/1 -> "pipe:[1234]": a file descriptor, not
    // a name that can be replaced. Write through the name as given.
    if (link.string().rfind("/proc/", 0) == 0) return {OutputKind::stream, target};
    p = link.is_absolute() ? link : p.parent_path() / link;
  }
  return {is_regular_or_missing(p) ? OutputKind::replace : OutputKind::stream, p};
}

bool writes_to_standard_output(const fs::path& target) {
  if (target == "-") return true;
  struct stat out {
  }, file{};
  if (::fstat(STDOUT_FILENO, &out) != 0 || ::stat(target.c_str(), &file) != 0) return false;
  return out.st_dev == file.st_dev && out.st_ino == file.st_ino;
}

void remove_stale_temporaries_beside(const std::filesystem::path& target) {
  if (target.empty() || target == "-") return;
  try {
    const auto resolved = resolve_output(target);
    if (resolved.kind == OutputKind::replace)
      remove_stale_temporaries(resolved.path.parent_path().empty() ? std::filesystem::path(".")
                                                                   : resolved.path.parent_path());
  } catch (const FileWriteError&) {
    // A link loop: writing it fails with its own message.
  }
}

AtomicFile::AtomicFile(std::filesystem::path target, bool sync)
    : target_(std::move(target)), resolved_(resolve_output(target_)), sync_(sync) {
  switch (resolved_.kind) {
    case OutputKind::standard_output: fd_ = STDOUT_FILENO; return;
    case OutputKind::stream:
      // No O_CREAT, no O_TRUNC: the file exists and is not ours to recreate.
      // O_APPEND keeps what the shell's redirection already holds.
      fd_ = ::open(resolved_.path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
      if (fd_ < 0) {
        const int error = errno;
        throw FileWriteError("cannot write '" + target_.string() + "': " + errno_text(error));
      }
      return;
    case OutputKind::replace: break;
  }
  temporary_ = temporary_path_for(resolved_.path);
  install_temporary_cleanup();
  // Registered before it exists, so a signal during open() cannot leave it behind.
  cleanup_slot_ = register_temporary(temporary_);
  // O_TRUNC: a temporary left by a crashed run of this pid is stale; start over.
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    const int error = errno;
    unregister_temporary(cleanup_slot_);
    cleanup_slot_ = -1;
    throw FileWriteError("cannot write '" + target_.string() + "': cannot create temporary '" +
                         temporary_.string() + "': " + errno_text(error));
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) discard();
}

void AtomicFile::discard() noexcept {
  if (fd_ >= 0 && fd_ != STDOUT_FILENO) ::close(fd_);
  fd_ = -1;
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  unregister_temporary(cleanup_slot_);
  cleanup_slot_ = -1;
}

void AtomicFile::fail(const std::string& what, int error) {
  discard();
  throw FileWriteError("cannot write '" + target_.string() + "': " + what + errno_text(error));
}

void AtomicFile::write(std::span<const std::byte> data) {
  if (fd_ < 0) throw FileWriteError("cannot write '" + target_.string() + "': file already closed");
  const auto* bytes = reinterpret_cast<const char*>(data.data());
  std::size_t left = data.size();
  while (left > 0) {
    const ssize_t written = ::write(fd_, bytes, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      fail("", errno);
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
  if (resolved_.kind == OutputKind::standard_output) {
    fd_ = -1;
    committed_ = true;
    return;
  }
  if (sync_ && resolved_.kind == OutputKind::replace && ::fsync(fd_) != 0) fail("fsync: ", errno);
  // close() can report a deferred write error (NFS, quota): check it.
  const int closed = ::close(fd_);
  fd_ = -1;
  if (closed != 0) fail("close: ", errno);
  if (resolved_.kind == OutputKind::replace &&
      std::rename(temporary_.c_str(), resolved_.path.c_str()) != 0)
    fail("rename from '" + temporary_.string() + "': ", errno);
  unregister_temporary(cleanup_slot_);
  cleanup_slot_ = -1;
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
