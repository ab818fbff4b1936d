// What the first integration in a process costs beyond the later ones. Each
// sample is a fresh process (this program re-run with --child), which times
// its first and second run of the same short integration (Kovalevskaya,
// T = 10, DOP853 tol 1e-10, 100 output samples) and counts the page faults
// each one takes; the parent prints medians over the children.
//
//   build/bench/epviz_first_run_bench [children]
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "sim/simulate.hpp"

extern char** environ;

namespace {

using namespace epviz;

long page_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt + u.ru_majflt;
}

struct Timed {
  double micros;
  long faults;
};

Timed one_run(const sim::RunSpec& spec) {
  const long f0 = page_faults();
  const auto t0 = std::chrono::steady_clock::now();
  const sim::RunResult r = sim::simulate(spec);
  const auto t1 = std::chrono::steady_clock::now();
  if (r.failure) std::abort();
  return {std::chrono::duration<double, std::micro>(t1 - t0).count(), page_faults() - f0};
}

int child() {
  sim::RunSpec spec = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                                      sim::Formulation::direct, 10.0, 100);
  spec.tol = 1e-10;
  const Timed first = one_run(spec);
  const Timed second = one_run(spec);
  std::printf("%.3f %ld %.3f %ld\n", first.micros, first.faults, second.micros, second.faults);
  return 0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--child") == 0) return child();
  const int children = argc > 1 ? std::max(1, std::atoi(argv[1])) : 21;
  std::vector<double> first_us, second_us, first_faults, second_faults;
  for (int i = 0; i < children; ++i) {
    int out[2];
    if (pipe(out) != 0) return 1;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    std::string self = "/proc/self/exe", flag = "--child";
    char* args[] = {self.data(), flag.data(), nullptr};
    pid_t pid = 0;
    if (posix_spawn(&pid, self.c_str(), &actions, nullptr, args, environ) != 0) return 1;
    posix_spawn_file_actions_destroy(&actions);
    close(out[1]);
    char buf[256] = {};
    const ssize_t n = read(out[0], buf, sizeof buf - 1);
    close(out[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    double a = 0, c = 0;
    long b = 0, d = 0;
    if (n <= 0 || std::sscanf(buf, "%lf %ld %lf %ld", &a, &b, &c, &d) != 4) return 1;
    first_us.push_back(a);
    first_faults.push_back(double(b));
    second_us.push_back(c);
    second_faults.push_back(double(d));
  }
  std::printf("first run in a process:  %8.1f us, %3.0f page faults (median of %d processes)\n",
              median(first_us), median(first_faults), children);
  std::printf("second run:              %8.1f us, %3.0f page faults\n", median(second_us),
              median(second_faults));
  std::printf("first / second:          %8.1fx\n", median(first_us) / median(second_us));
  return 0;
}
