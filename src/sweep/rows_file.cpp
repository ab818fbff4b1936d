#include "sweep/rows_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "io/json_text.hpp"
#include "shard/merged_rows.hpp"

namespace epviz::sweep {

namespace fs = std::filesystem;

ExistingRows resume_rows(const fs::path& path, const std::string& sweep_hash, long points,
                         shard::ItemRange mine) {
  ExistingRows out;
  std::error_code ec;
  if (!fs::exists(path, ec)) return out;
  if (!fs::is_regular_file(path, ec))
    throw RowsFileError(path.string() + ": not a regular file (rows are appended to a file)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RowsFileError(path.string() + ": cannot read (" + std::strerror(errno) + ")");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  // By index: the line number and text of its first row (in `text`).
  std::map<long, std::pair<long, std::string_view>> first_row;
  std::optional<std::string> kept;  // the lines that stay, once one does not
  std::size_t pos = 0;
  long line_no = 0;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    if (nl == std::string::npos) break;  // torn: no end of line
    ++line_no;
    const std::string_view line(text.data() + pos, nl - pos);
    pos = nl + 1;
    auto bad = [&](const std::string& why) {
      throw RowsFileError(path.string() + ": line " + std::to_string(line_no) + " " + why +
                          "; give another --out, or remove the file to start over");
    };
    nlohmann::json row;
    try {
      row = io::parse_json(line);
    } catch (const nlohmann::json::exception&) {
      bad("is not a JSON row");
    }
    if (!row.is_object() || !row.contains("sweep") || !row.contains("index") ||
        !row["index"].is_number_integer())
      bad("is not a row of a sweep");
    if (row["sweep"] != sweep_hash) bad("is a row of another sweep (or of an edited sweep file)");
    const long index = row["index"].get<long>();
    if (index < 0 || index >= points) bad("has an index outside this sweep");
    if (index < mine.first || index >= mine.end)
      bad("holds point " + std::to_string(index) + ", outside this shard's points " +
          std::to_string(mine.first) + ".." + std::to_string(mine.end - 1));
    const auto [it, first] = first_row.try_emplace(index, line_no, line);
    if (!first) {
      const auto& [earlier_no, earlier] = it->second;
      if (earlier != line && !shard::same_row(io::parse_json(earlier), row))
        bad("and line " + std::to_string(earlier_no) + " are different rows of point " +
            std::to_string(index));
      if (!kept) kept = text.substr(0, std::size_t(line.data() - text.data()));
      ++out.dropped_duplicates;
      continue;
    }
    if (kept) {
      *kept += line;
      *kept += '\n';
    }
    out.indices.insert(index);
  }
  out.dropped_torn = pos < text.size();
  if (kept) {
    io::write_file_atomically(path, *kept);
  } else if (out.dropped_torn) {
    fs::resize_file(path, pos, ec);
    if (ec)
      throw RowsFileError(path.string() + ": cannot cut off the torn last line (" + ec.message() +
                          ")");
  }
  return out;
}

std::string repairs_note(const ExistingRows& rows) {
  std::string note;
  if (rows.dropped_torn) note = "a torn last line dropped";
  if (rows.dropped_duplicates) {
    if (!note.empty()) note += ", ";
    note += std::to_string(rows.dropped_duplicates) + " duplicate rows dropped";
  }
  return note.empty() ? note : " (" + note + ")";
}

namespace {
// A row waits at most this long to be written; rows that finish within it are
// written together (up to kGatherBytes), so short points cost no system call each.
constexpr auto kGatherTime = std::chrono::milliseconds(200);
constexpr std::size_t kGatherBytes = 64 * 1024;
}  // namespace

RowAppender::RowAppender(const fs::path& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw RowsFileError(path.string() + ": cannot open for appending (" + std::strerror(errno) +
                        ")");
  writer_ = std::thread([this] { write_periodically(); });
}

RowAppender::~RowAppender() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  writer_.join();
  try {
    flush();
  } catch (const RowsFileError&) {
    // Already failing (or being unwound): the rows not written are recomputed on resume.
  }
  ::close(fd_);
}

void RowAppender::write_periodically() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, kGatherTime);
    if (gathered_.empty() || error_) continue;
    try {
      write_gathered();
    } catch (const RowsFileError&) {
      error_ = std::current_exception();  // the next append or flush reports it
    }
  }
}

void RowAppender::append(const std::string& line) {
  std::lock_guard lock(mutex_);
  if (error_) std::rethrow_exception(error_);
  gathered_ += line;
  gathered_ += '\n';
  if (gathered_.size() >= kGatherBytes) write_gathered();
}

void RowAppender::flush() {
  std::lock_guard lock(mutex_);
  if (error_) std::rethrow_exception(error_);
  write_gathered();
}

void RowAppender::write_gathered() {
  std::size_t done = 0;
  while (done < gathered_.size()) {
    const ssize_t n = ::write(fd_, gathered_.data() + done, gathered_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw RowsFileError(path_.string() + ": write failed (" + std::strerror(errno) + ")");
    done += std::size_t(n);
  }
  gathered_.clear();
}

}  // namespace epviz::sweep
