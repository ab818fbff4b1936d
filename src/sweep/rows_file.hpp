#pragma once
// The JSON Lines file a sweep writes: one row per point, appended as points
// finish (in whatever order the threads finish them) and written within 0.2 s
// of finishing, so that a sweep that is killed loses at most the rows being
// computed and those of the last 0.2 s. Starting again on the
// same file resumes: complete rows are kept and their points skipped; a last
// line cut short by the kill is removed.
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

namespace epviz::sweep {

class RowsFileError : public io::BadInput {
 public:
  using io::BadInput::BadInput;
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
