#pragma once
// The render progress line: "frames done/total, frames/s, ETA", redrawn in
// place with '\r' at most every `min_interval` (0.2 s: ~5 times a second) and
// ended with a newline by finish(). Quiet when stderr is not a terminal, so
// logs and CI output get no '\r' noise; tests force it on with a stream.
//
//   epviz: 120/600 frames, 64.3 frames/s, ETA 0:07
#include <chrono>
#include <functional>
#include <iosfwd>
#include <string>

namespace epviz::io {

enum class ProgressMode {
  automatic,  // on if stderr (file descriptor 2) is a terminal
  on,         // always (tests, --progress)
  off,        // never (--quiet)
};

struct ProgressOptions {
  ProgressMode mode = ProgressMode::automatic;
  std::ostream* out = nullptr;  // nullptr: std::cerr
  std::string label;            // printed before the counts with ": " when not empty
  std::string unit = "frames";  // what is counted: "frames", "samples"
  int already_done = 0;         // frames done before this run (--resume): not counted in frames/s
  std::chrono::duration<double> min_interval{0.2};
  // Time source, injectable for tests; default std::chrono::steady_clock::now.
  std::function<std::chrono::steady_clock::time_point()> clock;
};

// "0:07", "12:05", "1:02:03" (seconds rounded up); "--:--" for a negative or unknown value.
std::string format_eta(double seconds);

// The line's text without '\r' or padding.
std::string format_progress(const std::string& label, int done, int total, double frames_per_second,
                            double eta_seconds, const std::string& unit = "frames");

class ProgressLine {
 public:
  explicit ProgressLine(int total, ProgressOptions options = {});
  ~ProgressLine();  // finish()es, errors ignored
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // `done` frames are complete (absolute count). Redraws if the last redraw
  // is older than min_interval (the first update always draws).
  void update(int done);
  // One more frame done (or n).
  void advance(int n = 1) { update(done_ + n); }
  // Draws the final state and a newline (only if something is shown); idempotent.
  void finish();

  bool enabled() const { return enabled_; }
  int done() const { return done_; }
  int total() const { return total_; }

 private:
  std::chrono::steady_clock::time_point now() const;
  void draw(std::chrono::steady_clock::time_point now);

  ProgressOptions options_;
  std::ostream* out_;
  int total_;
  int done_ = 0;
  bool enabled_ = false;
  bool drawn_ = false;
  bool finished_ = false;
  std::size_t last_length_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace epviz::io
