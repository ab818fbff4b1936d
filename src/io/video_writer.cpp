#include "io/video_writer.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/errno_text.hpp"
#include "io/temp_registry.hpp"

namespace epviz::io {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kNotFound =
    "ffmpeg not found on PATH: install the Debian package ffmpeg (scripts/setup.sh does)";

bool is_executable_file(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
         ::access(path.c_str(), X_OK) == 0;
}

std::string format_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace

bool ffmpeg_available(const std::string& program) {
  if (program.empty()) return false;
  if (program.find('/') != std::string::npos) return is_executable_file(program);
  const char* env = std::getenv("PATH");
  const std::string_view path = env ? env : "/usr/local/bin:/usr/bin:/bin";
  std::size_t start = 0;
  while (true) {
    const std::size_t end = path.find(':', start);
    const std::string_view dir =
        path.substr(start, end == std::string_view::npos ? path.size() - start : end - start);
    // An empty PATH entry means the current directory.
    const fs::path candidate = fs::path(dir.empty() ? std::string_view(".") : dir) / program;
    if (is_executable_file(candidate.string())) return true;
    if (end == std::string_view::npos) return false;
    start = end + 1;
  }
}

std::vector<std::string> ffmpeg_arguments(VideoFormat format, int width, int height, double fps,
                                          const fs::path& output, const VideoOptions& options) {
  std::vector<std::string> args = {
      options.ffmpeg, "-hide_banner",
      "-nostdin",     "-loglevel",
      "error",        "-y",
      "-f",           "rawvideo",
      "-pix_fmt",     "rgba",
      "-s",           std::to_string(width) + "x" + std::to_string(height),
      "-r",           format_number(fps),
      "-i",           "-",
      "-an"};
  auto add = [&args](std::initializer_list<std::string> more) { args.insert(args.end(), more); };
  switch (format) {
    case VideoFormat::mp4:
      add({"-c:v", "libx264", "-preset", options.x264_preset, "-crf",
           std::to_string(options.crf >= 0 ? options.crf : 23), "-pix_fmt", "yuv420p", "-movflags",
           "+faststart", "-f", "mp4"});
      break;
    case VideoFormat::webm:
      add({"-c:v", "libvpx-vp9", "-deadline", "realtime", "-cpu-used", "8", "-row-mt", "1", "-b:v",
           "0", "-crf", std::to_string(options.crf >= 0 ? options.crf : 35), "-pix_fmt", "yuv420p",
           "-f", "webm"});
      break;
    case VideoFormat::gif:
      add({"-vf",
           "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer:bayer_scale="
           "5",
           "-loop", "0", "-f", "gif"});
      break;
  }
  args.push_back(output.string());
  return args;
}

VideoWriter::VideoWriter(fs::path target, VideoFormat format, int width, int height, double fps,
                         VideoOptions options)
    : target_(std::move(target)),
      temporary_(temporary_path_for(target_)),
      format_(format),
      width_(width),
      height_(height) {
  if (const auto why = video_size_problem(format, width, height); !why.empty())
    throw std::invalid_argument("video '" + target_.string() + "': " + why);
  if (!(fps > 0.0) || fps > 1000.0)
    throw std::invalid_argument("video '" + target_.string() + "': frame rate " +
                                format_number(fps) + " must be in (0, 1000]");
  frame_bytes_ = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;

  fs::path dir = target_.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw VideoError("cannot write video '" + target_.string() + "': directory '" + dir.string() +
                     "' does not exist or is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    const int error = errno;
    throw VideoError("cannot write video '" + target_.string() + "': directory '" + dir.string() +
                     "' is not writable: " + errno_text(error));
  }
  if (!ffmpeg_available(options.ffmpeg)) {
    if (options.ffmpeg.find('/') != std::string::npos)
      throw VideoError("cannot write video '" + target_.string() + "': ffmpeg not found at '" +
                       options.ffmpeg +
                       "': install the Debian package ffmpeg (scripts/setup.sh does)");
    throw VideoError("cannot write video '" + target_.string() + "': " + std::string(kNotFound));
  }

  // ffmpeg's stderr: an unlinked temporary, read back only when ffmpeg fails.
  std::string stderr_name = (fs::temp_directory_path() / "epviz-ffmpeg-stderr-XXXXXX").string();
  stderr_fd_ = ::mkostemp(stderr_name.data(), O_CLOEXEC);
  if (stderr_fd_ < 0) {
    const int error = errno;
    throw VideoError(
        "cannot write video '" + target_.string() +
        "': cannot create a temporary file for ffmpeg's messages: " + errno_text(error));
  }
  ::unlink(stderr_name.c_str());

  // A stale temporary of this pid (an earlier crash) is overwritten by -y.
  Subprocess::Options streams;
  streams.out = Subprocess::Stream::null;
  streams.err = Subprocess::Stream::fd;
  streams.err_fd = stderr_fd_;
  try {
    ffmpeg_ = std::make_unique<Subprocess>(
        ffmpeg_arguments(format, width, height, fps, temporary_, options), streams);
  } catch (const SubprocessError& e) {
    ::close(stderr_fd_);
    stderr_fd_ = -1;
    if (e.errno_value == ENOENT)
      throw VideoError("cannot write video '" + target_.string() + "': " + std::string(kNotFound));
    throw VideoError("cannot write video '" + target_.string() + "': cannot start " +
                     options.ffmpeg + ": " + errno_text(e.errno_value));
  }
  install_temporary_cleanup();
  cleanup_slot_ = register_temporary(temporary_, ffmpeg_->pid());
}

VideoWriter::~VideoWriter() {
  if (!finished_) abort();
}

ExitStatus VideoWriter::wait_for_exit() noexcept {
  if (!ffmpeg_) return {};
  ffmpeg_->close_stdin();
  const ExitStatus status = ffmpeg_->wait();
  forget_child(cleanup_slot_);
  ffmpeg_.reset();
  return status;
}

void VideoWriter::abort() noexcept {
  if (ffmpeg_) {
    ffmpeg_->close_stdin();
    ffmpeg_->kill(SIGKILL);
    wait_for_exit();
  }
  ::unlink(temporary_.c_str());
  unregister_temporary(cleanup_slot_);
  cleanup_slot_ = -1;
  if (stderr_fd_ >= 0) {
    ::close(stderr_fd_);
    stderr_fd_ = -1;
  }
}

std::string VideoWriter::ffmpeg_stderr() const {
  if (stderr_fd_ < 0) return {};
  struct stat info {};
  if (::fstat(stderr_fd_, &info) != 0 || info.st_size <= 0) return {};
  // The end of a long log is where the cause is; keep the last 4000 bytes.
  constexpr off_t kKeep = 4000;
  const off_t start = info.st_size > kKeep ? info.st_size - kKeep : 0;
  std::string text(static_cast<std::size_t>(info.st_size - start), '\0');
  std::size_t got = 0;
  while (got < text.size()) {
    const ssize_t n =
        ::pread(stderr_fd_, text.data() + got, text.size() - got, start + static_cast<off_t>(got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  text.resize(got);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
    text.pop_back();
  return text;
}

void VideoWriter::fail(const std::string& what) {
  const ExitStatus status = wait_for_exit();
  std::string message = "cannot write video '" + target_.string() + "': " + what;
  if (status.raw != -1) message += "; ffmpeg " + status.describe();
  const std::string log = ffmpeg_stderr();
  message += log.empty() ? std::string(" (no message from ffmpeg)") : ":\n" + log;
  abort();
  throw VideoError(message);
}

void VideoWriter::write_frame(std::span<const std::uint8_t> rgba) {
  if (rgba.size() != frame_bytes_)
    throw std::invalid_argument("video '" + target_.string() + "': frame has " +
                                std::to_string(rgba.size()) + " bytes, expected " +
                                std::to_string(frame_bytes_) + " (" + std::to_string(width_) + "x" +
                                std::to_string(height_) + " RGBA)");
  write_frame(rgba.data());
}

void VideoWriter::write_frame(const std::uint8_t* rgba) {
  if (finished_)
    throw VideoError("cannot write video '" + target_.string() + "': already finished");
  if (!ffmpeg_)
    throw VideoError("cannot write video '" + target_.string() +
                     "': the writer has already failed");
  const int error = ffmpeg_->write_stdin(rgba, frame_bytes_);
  if (error == EPIPE) fail("ffmpeg stopped reading frames after " + std::to_string(frames_));
  if (error != 0) fail("writing a frame to ffmpeg: " + errno_text(error));
  ++frames_;
}

void VideoWriter::finish() {
  if (finished_) return;
  if (!ffmpeg_)
    throw VideoError("cannot write video '" + target_.string() +
                     "': the writer has already failed");
  if (frames_ == 0) {
    abort();
    throw VideoError("cannot write video '" + target_.string() + "': no frames were written");
  }
  const ExitStatus status = wait_for_exit();
  if (!status.success()) {
    std::string message =
        "cannot write video '" + target_.string() + "': ffmpeg " + status.describe();
    const std::string log = ffmpeg_stderr();
    message += log.empty() ? std::string(" (no message from ffmpeg)") : ":\n" + log;
    abort();
    throw VideoError(message);
  }
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
    const int error = errno;
    abort();
    throw VideoError("cannot write video '" + target_.string() + "': cannot rename '" +
                     temporary_.string() + "': " + errno_text(error));
  }
  unregister_temporary(cleanup_slot_);
  cleanup_slot_ = -1;
  if (stderr_fd_ >= 0) {
    ::close(stderr_fd_);
    stderr_fd_ = -1;
  }
  finished_ = true;
}

}  // namespace epviz::io
