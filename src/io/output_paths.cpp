#include "io/output_paths.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <system_error>

#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/errno_text.hpp"
#include "io/printable.hpp"

namespace epviz::io {
namespace {

namespace fs = std::filesystem;

// Room left in a file name for "_000123.png" or a temporary's suffix (34
// characters, io/temp_name.hpp) after output.name.
constexpr std::size_t kLongestName = 200;

// Bounded and escaped: a path comes from the user and may be kilobytes long
// or hold a newline; the message stays one short line.
std::string in_quotes(const fs::path& p) {
  std::string text(1, '\'');
  text += printable(p.string(), 200);
  text += '\'';
  return text;
}

// Longer than the system takes (a name over NAME_MAX bytes, a path over
// PATH_MAX): refused here, before work, not by the first mkdir.
bool too_long(const fs::path& absolute) {
  if (absolute.native().size() >= PATH_MAX) return true;
  for (const fs::path& part : absolute)
    if (part.native().size() > NAME_MAX) return true;
  return false;
}

bool writable_directory(const fs::path& dir) { return ::access(dir.c_str(), W_OK | X_OK) == 0; }

// What a path names, so that every spelling of one file compares equal.
struct FileIdentity {
  bool skipped = false;  // nothing to compare: see require_separate_files
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  fs::path path;  // when it does not exist yet: absolute, normalized, links resolved

  bool operator==(const FileIdentity& o) const {
    if (skipped || o.skipped || exists != o.exists) return false;
    return exists ? device == o.device && inode == o.inode : path == o.path;
  }
};

// Symbolic links are followed as the writer follows them; a dangling one
// stands for the file it would create.
FileIdentity identity_of(const std::string& path) {
  FileIdentity id;
  if (path.empty() || path == "-") {
    id.skipped = true;
    return id;
  }
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    id.skipped = S_ISCHR(st.st_mode);
    id.exists = true;
    id.device = st.st_dev;
    id.inode = st.st_ino;
    return id;
  }
  fs::path target = path;
  try {
    target = resolve_output(path).path;
  } catch (const FileWriteError&) {
    // A link loop: compared as spelled; writing it fails later anyway.
  }
  std::error_code ec;
  auto p = fs::weakly_canonical(fs::absolute(target, ec), ec);
  id.path = ec ? fs::absolute(target).lexically_normal() : p;
  return id;
}

}  // namespace

void check_output_file(const std::string& option, const std::string& path) {
  if (path.empty() || path == "-") return;
  if (path.back() == '/')
    throw BadInput(option + ": " + in_quotes(path) + " names a directory; give a file name");
  OutputTarget target;
  try {
    target = resolve_output(path);
  } catch (const FileWriteError& e) {
    throw BadInput(option + ": " + e.what());
  }
  if (target.kind == OutputKind::stream) {
    std::error_code ec;
    if (fs::is_directory(target.path, ec))
      throw BadInput(option + ": " + in_quotes(path) + " is a directory; give a file name");
    if (::access(target.path.c_str(), W_OK) != 0)
      throw BadInput(option + ": cannot write " + in_quotes(path) + ": " + errno_text(errno));
    return;
  }
  fs::path dir = target.path.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw BadInput(option + ": directory " + in_quotes(fs::absolute(dir)) + " does not exist");
  if (!writable_directory(dir))
    throw BadInput(option + ": directory " + in_quotes(fs::absolute(dir)) +
                   " is not writable: " + errno_text(errno));
}

void require_separate_files(const NamedPaths& inputs, const NamedPaths& outputs) {
  std::vector<FileIdentity> read, written;
  for (const auto& [name, path] : inputs) read.push_back(identity_of(path));
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const auto& [option, path] = outputs[i];
    written.push_back(identity_of(path));
    for (std::size_t j = 0; j < inputs.size(); ++j)
      if (written[i] == read[j])
        throw BadInput(option + ": " + in_quotes(path) + " is the same file as " + inputs[j].first +
                       " (" + in_quotes(inputs[j].second) +
                       "), which this run reads; give the output another file");
    for (std::size_t j = 0; j < i; ++j)
      if (written[i] == written[j])
        throw BadInput(option + ": " + in_quotes(path) + " is the same file as " +
                       outputs[j].first + " (" + in_quotes(outputs[j].second) +
                       "); give each output its own file");
  }
}

void check_output_dir(const std::string& what, const fs::path& dir) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(dir, ec);
  if (too_long(absolute))
    throw BadInput(what + ": " + in_quotes(dir) + " is too long (at most " +
                   std::to_string(NAME_MAX) + " bytes a name, " + std::to_string(PATH_MAX - 1) +
                   " bytes the whole path)");
  fs::path existing = absolute;
  while (!fs::exists(existing, ec) && existing.has_relative_path())
    existing = existing.parent_path();
  if (!fs::is_directory(existing, ec)) {
    if (existing == absolute)
      throw BadInput(what + ": " + in_quotes(dir) + " exists and is not a directory");
    throw BadInput(what + ": cannot create " + in_quotes(dir) + ": " + in_quotes(existing) +
                   " is not a directory");
  }
  if (!writable_directory(existing)) {
    const int error = errno;
    if (existing == absolute)
      throw BadInput(what + ": directory " + in_quotes(dir) +
                     " is not writable: " + errno_text(error));
    throw BadInput(what + ": cannot create " + in_quotes(dir) + ": " + in_quotes(existing) +
                   " is not writable: " + errno_text(error));
  }
}

void check_file_name(const std::string& what, const std::string& name) {
  const char* allowed =
      ": expected a file name: not empty, not '.' or '..', without '/', NUL or control characters, "
      "at most 200 bytes";
  bool bad = name.empty() || name == "." || name == ".." || name.size() > kLongestName;
  for (const unsigned char c : name) bad = bad || c == '/' || c < 0x20 || c == 0x7f;
  if (bad) throw BadInput(what + allowed);
}

FifoReaderCheck::FifoReaderCheck(const std::string& option, const std::string& target) {
  std::error_code ec;
  if (target.empty() || !fs::is_fifo(target, ec)) return;
  fd_ = ::open(target.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0)
    throw BadInput(option + ": '" + printable(target, 200) + "' is a FIFO that " +
                   (errno == ENXIO ? std::string("nobody reads")
                                   : "cannot be opened: " + std::string(std::strerror(errno))));
}

FifoReaderCheck::~FifoReaderCheck() {
  if (fd_ >= 0) ::close(fd_);
}

void make_output_folder(const std::string& option, const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  const auto probe = fs::path(dir) / (".epviz-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0)
    throw BadInput(option + ": cannot create files in '" + printable(dir, 200) +
                   "': " + std::strerror(errno));
  ::close(fd);
  fs::remove(probe);
}

}  // namespace epviz::io
