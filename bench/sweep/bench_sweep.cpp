// What a sweep point costs, in one run: the same short runs (Kovalevskaya,
// T = 10, dop853 at tol 1e-10, omega[0] varied) done four ways —
//   bare loop        sim::simulate in a plain loop: the integration alone
//   sweep in-process sweep::run_points on one thread: rows built and appended
//   epviz sweep      the command, as a process (-j 1), start-up and reading included
//   shell loop       `epviz simulate` once per run, as a shell loop would
// and the ratios to the bare loop, per core.
//
//   epviz_sweep_bench [POINTS] [SHELL_RUNS]      (default 2000 and 40)
#include <unistd.h>
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

}  // namespace

int main(int argc, char** argv) {
  const long points = argc > 1 ? std::atol(argv[1]) : 2000;
  const long shell_runs = argc > 2 ? std::atol(argv[2]) : 40;
  const std::string epviz = EPVIZ_BINARY;
  const fs::path dir =
      fs::temp_directory_path() / ("epviz-sweep-bench-" + std::to_string(::getpid()));
  fs::create_directories(dir);

  // Bare loop.
  auto t0 = Clock::now();
  long steps = 0;
  for (long i = 0; i < points; ++i) steps += sim::simulate(run_of(omega0(i, points))).stats.steps;
  const double bare = seconds_since(t0);

  // In-process sweep on one thread.
  sweep::SweepSpec spec;
  spec.hash = "bench";
  std::vector<sweep::PreparedPoint> prepared;
  for (long i = 0; i < points; ++i) {
    sweep::PreparedPoint p;
    p.point.index = i;
    p.point.axis_values["omega[0]"] = omega0(i, points);
    p.run = run_of(omega0(i, points));
    prepared.push_back(std::move(p));
  }
  t0 = Clock::now();
  {
    sweep::RowAppender rows(dir / "rows.jsonl");
    sweep::run_points(spec, prepared, 1, rows);
  }
  const double in_process = seconds_since(t0);

  // The command.
  std::ofstream(dir / "bench.sweep.json")
      << R"({"simulation": {"case": "kovalevskaya", "t_end": 10, "samples": 100, "method": "dop853", "tol": 1e-10},
            "axes": [{"field": "omega[0]", "from": 0.5, "to": 1.5, "count": )"
      << points << "}]}";
  t0 = Clock::now();
  auto r = io::run_process({epviz, "sweep", (dir / "bench.sweep.json").string(), "--out",
                            (dir / "cmd.jsonl").string(), "-j", "1", "--quiet"});
  const double command = seconds_since(t0);
  if (!r.status.success()) {
    std::fprintf(stderr, "epviz sweep %s: %s\n", r.status.describe().c_str(), r.err.c_str());
    return 1;
  }

  // A shell loop of epviz simulate (a few runs: each is a process start).
  t0 = Clock::now();
  for (long i = 0; i < shell_runs; ++i) {
    char w[96];
    std::snprintf(w, sizeof w, "%.17g,%.17g,%.17g", omega0(i, shell_runs),
                  run_of(0).initial.omega[1], run_of(0).initial.omega[2]);
    auto s = io::run_process({epviz, "simulate", "--case", "kovalevskaya", "--t-end", "10",
                              "--samples", "100", "--method", "dop853", "--tol", "1e-10", "--omega",
                              w, "--report-json", (dir / "r.json").string()});
    if (!s.status.success()) {
      std::fprintf(stderr, "epviz simulate %s: %s\n", s.status.describe().c_str(), s.err.c_str());
      return 1;
    }
  }
  const double shell = seconds_since(t0);
  fs::remove_all(dir);

  const double base = double(points) / bare;
  auto line = [&](const char* name, long n, double s) {
    const double rate = double(n) / s;
    std::printf("%-22s %8ld runs %9.3f s %10.1f runs/s/core %8.2fx the bare loop's cost\n", name, n,
                s, rate, base / rate);
  };
  std::printf(
      "Kovalevskaya, T = 10, dop853 tol 1e-10, 100 samples; %.0f steps per run on average\n",
      double(steps) / double(points));
  line("bare loop", points, bare);
  line("sweep, in-process", points, in_process);
  line("epviz sweep -j 1", points, command);
  line("shell loop of simulate", shell_runs, shell);
  std::printf("epviz sweep is %.0fx faster per run than a shell loop of epviz simulate\n",
              (shell / double(shell_runs)) / (command / double(points)));
  return 0;
}
