#include "io/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace epviz::io {

std::string format_eta(double seconds) {
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) return "--:--";
  const long long total = static_cast<long long>(std::ceil(seconds));
  const long long h = total / 3600, m = (total / 60) % 60, s = total % 60;
  char buffer[48];
  if (h > 0)
    std::snprintf(buffer, sizeof buffer, "%lld:%02lld:%02lld", h, m, s);
  else
    std::snprintf(buffer, sizeof buffer, "%lld:%02lld", m, s);
  return buffer;
}

std::string format_progress(const std::string& label, int done, int total, double frames_per_second,
                            double eta_seconds, const std::string& unit) {
  char rate[32];
  if (frames_per_second > 0.0 && std::isfinite(frames_per_second))
    std::snprintf(rate, sizeof rate, "%.1f", frames_per_second);
  else
    std::snprintf(rate, sizeof rate, "--");
  std::string line = label.empty() ? std::string() : label + ": ";
  line += std::to_string(done) + "/" + std::to_string(total) + " " + unit + ", " + rate + " " +
          unit + "/s, ETA " + format_eta(eta_seconds);
  return line;
}

ProgressLine::ProgressLine(int total, ProgressOptions options)
    : options_(std::move(options)),
      out_(options_.out ? options_.out : &std::cerr),
      total_(total < 0 ? 0 : total),
      done_(options_.already_done) {
  switch (options_.mode) {
    case ProgressMode::on: enabled_ = true; break;
    case ProgressMode::off: enabled_ = false; break;
    case ProgressMode::automatic: enabled_ = ::isatty(STDERR_FILENO) == 1; break;
  }
  start_ = now();
  last_draw_ = start_;
}

ProgressLine::~ProgressLine() {
  try {
    finish();
  } catch (...) {
  }
}

std::chrono::steady_clock::time_point ProgressLine::now() const {
  return options_.clock ? options_.clock() : std::chrono::steady_clock::now();
}

void ProgressLine::update(int done) {
  done_ = done;
  if (!enabled_ || finished_) return;
  const auto t = now();
  if (drawn_ && t - last_draw_ < options_.min_interval) return;
  draw(t);
}

void ProgressLine::draw(std::chrono::steady_clock::time_point t) {
  const double elapsed = std::chrono::duration<double>(t - start_).count();
  const int counted = done_ - options_.already_done;
  const double rate = elapsed > 0.0 && counted > 0 ? counted / elapsed : 0.0;
  const double eta = rate > 0.0 ? (total_ - done_) / rate : (done_ >= total_ ? 0.0 : -1.0);
  std::string line =
      format_progress(options_.label, done_, total_, rate, eta < 0.0 ? -1.0 : eta, options_.unit);
  const std::size_t length = line.size();
  // Blank out what is left of a longer previous line.
  if (length < last_length_) line.append(last_length_ - length, ' ');
  last_length_ = length;
  *out_ << '\r' << line << std::flush;
  drawn_ = true;
  last_draw_ = t;
}

void ProgressLine::finish() {
  if (finished_) return;
  finished_ = true;
  if (!enabled_) return;
  draw(now());
  *out_ << '\n' << std::flush;
}

}  // namespace epviz::io
