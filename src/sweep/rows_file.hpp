#pragma once
// The JSON Lines file a sweep writes: one row per point, appended as points
// finish (in whatever order the threads finish them) and written within 0.2 s
// of finishing, so that a sweep that is killed loses at most the rows being
// computed and those of the last 0.2 s. Starting again on the
// same file resumes: complete rows are kept and their points skipped; a last
// line cut short by the kill is removed, and so is a second row of a point
// that is the same as its first (shard::same_row).
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include "io/bad_input.hpp"
#include "shard/shard_spec.hpp"

namespace epviz::sweep {

class RowsFileError : public io::BadInput {
 public:
  using io::BadInput::BadInput;
};

struct ExistingRows {
  std::set<long> indices;       // points already done
  bool dropped_torn = false;    // a partial last line was removed
  long dropped_duplicates = 0;  // rows removed as copies of an earlier line
};

// Reads the rows already in `path` (none when it does not exist), cuts off a
// torn last line and removes rows the same as an earlier one of their point. Every complete
// line must be a row of the sweep with hash `sweep_hash` and an index in
// `mine` (this shard's points, or all `points` of an unsharded sweep), and
// two rows of one point must be the same; otherwise RowsFileError names the
// file and the line (both lines for two differing rows of a point), and the
// file is left as it was.
ExistingRows resume_rows(const std::filesystem::path& path, const std::string& sweep_hash,
                         long points, shard::ItemRange mine);
inline ExistingRows resume_rows(const std::filesystem::path& path, const std::string& sweep_hash,
                                long points) {
  return resume_rows(path, sweep_hash, points, {0, points});
}

// " (a torn last line dropped, 3 duplicate rows dropped)", or "" when
// nothing was repaired: for the line that reports the run.
std::string repairs_note(const ExistingRows& rows);

// Appends lines to a regular file (created if missing). Lines are gathered
// and written together, whole lines only, under a lock, so rows never
// interleave: by a thread of its own every 0.2 s, or at once when 64 KiB are
// gathered; short points then cost no system call each. A failed write is
// thrown by the next append or flush. flush() writes what is gathered (the
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
  void write_gathered();      // with mutex_ held
  void write_periodically();  // the writer thread
  std::filesystem::path path_;
  int fd_ = -1;
  std::mutex mutex_;
  std::condition_variable wake_;  // the destructor stops the writer through it
  std::string gathered_;
  std::exception_ptr error_;  // a write the writer thread could not make
  bool stopping_ = false;
  std::thread writer_;
};

}  // namespace epviz::sweep
