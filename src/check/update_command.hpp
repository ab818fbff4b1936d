#pragma once
// The command line that (re)creates goldens, printed with failures that only
// new goldens mend: missing, mis-sized or damaged goldens, a changed job.
#include <string>
#include <vector>

namespace epviz::check {

// "epviz check JOB --frames 0,3 [--golden DIR] [--gl B] --update", every word
// quoted for a POSIX shell where it needs to be. `golden_root` and `gl` are
// repeated when given (empty: not given), since the goldens depend on them.
std::string update_command(const std::string& job, const std::vector<int>& frames,
                           const std::string& golden_root, const std::string& gl);

}  // namespace epviz::check
