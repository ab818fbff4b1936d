#include "study/timing.hpp"

#include <algorithm>
#include <ctime>
#include <limits>

namespace epviz::study {

double cpu_seconds_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

int repeats_after_first(double first_cpu_seconds, int repeats) {
  return first_cpu_seconds > 0.5 ? std::min(repeats, 2) : repeats;
}

}  // namespace epviz::study
