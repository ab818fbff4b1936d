#include "check/frame_result.hpp"

namespace epviz::check {

std::string FrameResult::message() const {
  if (problem.empty()) return measure;
  if (measure.empty()) return problem;
  return measure + "; " + problem;
}

std::string FrameResult::line() const {
  return std::string(passed ? "PASS " : "FAIL ") + job + " frame " + std::to_string(frame) + ": " +
         message();
}

std::string summary(const std::vector<FrameResult>& results) {
  std::size_t passed = 0;
  for (const auto& r : results) passed += r.passed;
  return std::to_string(passed) + " passed, " + std::to_string(results.size() - passed) + " failed";
}

std::string update_summary(const std::vector<FrameResult>& results, int goldens_written) {
  std::size_t failed = 0;
  for (const auto& r : results) failed += !r.passed;
  return std::to_string(goldens_written) + " goldens written" +
         (failed ? ", " + std::to_string(failed) + " failed" : "");
}

bool all_passed(const std::vector<FrameResult>& results) {
  for (const auto& r : results)
    if (!r.passed) return false;
  return true;
}

}  // namespace epviz::check
