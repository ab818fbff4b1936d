#pragma once
// How the studies time a run: process CPU time (what the integration costs,
// whatever else the machine does), the median over repeats, and fewer repeats
// for long runs, whose timing noise is small. Shared by epviz's own runs and
// the C++ peers so that both are timed the same way.
#include <vector>

namespace epviz::study {

// CPU time of this process, in seconds (CLOCK_PROCESS_CPUTIME_ID).
double cpu_seconds_now();

// Median of the values (the mean of the middle two for an even count); NaN when empty.
double median(std::vector<double> values);

// How many times to run in all, given the first run's CPU seconds: `repeats`,
// or at most 2 when the first run took over half a second.
int repeats_after_first(double first_cpu_seconds, int repeats);

}  // namespace epviz::study
