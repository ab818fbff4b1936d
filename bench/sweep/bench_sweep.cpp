// What a sweep point costs, in one run: the same short runs (Kovalevskaya,
// T = 10, dop853 at tol 1e-10, omega[0] varied) done four ways —
//   bare loop        sim::simulate in a plain loop: the integration alone
//   sweep in-process sweep::run_points on one thread: rows built and appended
//   epviz sweep      the command, as a process (-j 1), start-up and reading included
//   shell loop       `epviz simulate` once per run, in a bash for loop
// and the ratios to the bare loop, per core; each the median of 3 rounds,
// after 200 runs that take the process's first-touch page faults.
//
//   epviz_sweep_bench [POINTS] [SHELL_RUNS]      (default 10000 and 100)
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/subprocess.hpp"
#include "physics/cases.hpp"
#include "sim/simulate.hpp"
#include "study/timing.hpp"
#include "sweep/sweep_runner.hpp"

namespace {

namespace fs = std::filesystem;
using namespace epviz;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double omega0(long i, long n) { return 0.5 + 1.0 * double(i) / double(std::max(1L, n - 1)); }

sim::RunSpec run_of(double w0) {
  const auto& p = physics::preset(physics::Case::kovalevskaya);
  sim::RunSpec r;
  r.case_id = physics::Case::kovalevskaya;
  r.body = p.body;
  r.initial = p.initial;
  r.initial.omega[0] = w0;
  r.method = sim::Method::dop853;
  r.tol = 1e-10;
  r.t_end = 10.0;
  r.samples = 100;
  return r;
}

// Seconds for one call of `f`: the median of `rounds` calls.
template <class F>
double median_seconds(int rounds, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < rounds; ++i) {
    const auto t0 = Clock::now();
    f();
    t.push_back(seconds_since(t0));
  }
  return study::median(std::move(t));
}

void must_succeed(const io::ProcessOutput& r, const char* what) {
  if (r.status.success()) return;
  std::fprintf(stderr, "%s %s: %s\n", what, r.status.describe().c_str(), r.err.c_str());
  std::exit(1);
}

}  // namespace

int main(int argc, char** argv) {
  const long points = argc > 1 ? std::atol(argv[1]) : 10000;
  const long shell_runs = argc > 2 ? std::atol(argv[2]) : 100;
  constexpr int kRounds = 3;
  const std::string epviz = EPVIZ_BINARY;
  const fs::path dir =
      fs::temp_directory_path() / ("epviz-sweep-bench-" + std::to_string(::getpid()));
  fs::create_directories(dir);

  // The first runs in a process pay for its first-touch page faults: not
  // part of what a point costs.
  for (long i = 0; i < 200; ++i) sim::simulate(run_of(omega0(i, 200)));

  // Bare loop.
  long steps = 0;
  const double bare = median_seconds(kRounds, [&] {
    steps = 0;
    for (long i = 0; i < points; ++i) steps += sim::simulate(run_of(omega0(i, points))).stats.steps;
  });

  // In-process sweep on one thread.
  sweep::SweepSpec spec;
  spec.hash = "bench";
  std::vector<sweep::PreparedPoint> prepared;
  for (long i = 0; i < points; ++i) {
    sweep::PointFields fields;
    fields.index = i;
    fields.axis_values["omega[0]"] = omega0(i, points);
    prepared.push_back(sweep::prepared_point(fields, run_of(omega0(i, points))));
  }
  const double in_process = median_seconds(kRounds, [&] {
    fs::remove(dir / "rows.jsonl");
    sweep::RowAppender rows(dir / "rows.jsonl");
    sweep::run_points(spec, prepared, 1, rows);
  });

  // The command.
  std::ofstream(dir / "bench.sweep.json")
      << R"({"simulation": {"case": "kovalevskaya", "t_end": 10, "samples": 100, "method": "dop853", "tol": 1e-10},
            "axes": [{"field": "omega[0]", "from": 0.5, "to": 1.5, "count": )"
      << points << "}]}";
  const double command = median_seconds(kRounds, [&] {
    fs::remove(dir / "cmd.jsonl");
    must_succeed(io::run_process({epviz, "sweep", (dir / "bench.sweep.json").string(), "--out",
                                  (dir / "cmd.jsonl").string(), "-j", "1", "--quiet"}),
                 "epviz sweep");
  });

  // A shell loop of epviz simulate, as a user would write it (fewer runs:
  // each is a process start).
  {
    std::ofstream loop(dir / "loop.sh");
    loop << "for w in";
    for (long i = 0; i < shell_runs; ++i) loop << ' ' << omega0(i, shell_runs);
    loop << "; do\n  '" << epviz
         << "' simulate --case kovalevskaya --t-end 10 --samples 100 --method dop853 --tol 1e-10 "
            "--omega \"$w,0.3,1.5\" --report-json '"
         << (dir / "r.json").string() << "' >/dev/null || exit 1\ndone\n";
  }
  const double shell = median_seconds(kRounds, [&] {
    must_succeed(io::run_process({"/bin/bash", (dir / "loop.sh").string()}), "shell loop");
  });
  fs::remove_all(dir);

  const double base = double(points) / bare;
  auto line = [&](const char* name, long n, double s) {
    const double rate = double(n) / s;
    std::printf("%-22s %8ld runs %9.3f s %10.1f runs/s/core %8.2fx the bare loop's cost\n", name, n,
                s, rate, base / rate);
  };
  std::printf(
      "Kovalevskaya, T = 10, dop853 tol 1e-10, 100 samples; %.0f steps per run on average; "
      "medians of %d\n",
      double(steps) / double(points), kRounds);
  line("bare loop", points, bare);
  line("sweep, in-process", points, in_process);
  line("epviz sweep -j 1", points, command);
  line("shell loop of simulate", shell_runs, shell);
  std::printf("epviz sweep is %.0fx faster per run than a shell loop of epviz simulate\n",
              (shell / double(shell_runs)) / (command / double(points)));
  return 0;
}
