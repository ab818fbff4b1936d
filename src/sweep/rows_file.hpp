#pragma once
// The JSON Lines file a sweep writes: one row per point, appended as points
// finish (in whatever order the threads finish them) and written out at least
// every 0.2 s, so that a sweep that is killed loses at most the rows being
// computed and those finished since the last write. Starting again on the
// same file resumes: complete rows are kept and their points skipped; a last
// line cut short by the kill is removed.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>

namespace epviz::sweep {

class RowsFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ExistingRows {
  std::set<long> indices;     // points already done
  bool dropped_torn = false;  // a partial last line was removed
};

// Reads the rows already in `path` (none when it does not exist) and cuts
// off a torn last line. Every complete line must be a row of the sweep with
// hash `sweep_hash` and an index below `points`; otherwise RowsFileError
// names the file and line (the file is left as it was).
ExistingRows resume_rows(const std::filesystem::path& path, const std::string& sweep_hash,
                         long points);

// Appends lines to a regular file (created if missing). Rows that finish
// within 0.2 s of the last write are gathered (up to 64 KiB) and written
// together, whole lines only, under a lock, so rows never interleave: short
// points then cost no system call each. flush() writes what is gathered (the
// destructor does too, ignoring errors).
class RowAppender {
 public:
  explicit RowAppender(const std::filesystem::path& path);
  ~RowAppender();
  RowAppender(const RowAppender&) = delete;
  RowAppender& operator=(const RowAppender&) = delete;
  void append(const std::string& line);  // `line` without its '\n'
  void flush();

 private:
  void write_gathered();  // with mutex_ held
  std::filesystem::path path_;
  int fd_ = -1;
  std::mutex mutex_;
  std::string gathered_;
  std::chrono::steady_clock::time_point last_write_ = std::chrono::steady_clock::now();
};

}  // namespace epviz::sweep
