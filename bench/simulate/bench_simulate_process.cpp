// `epviz simulate` as users run it, one process per run, against what its
// arithmetic allows and against its peers, in one run of this program:
//
//   equal error  Kovalevskaya preset, T = 300: the command's DOP853 (its
//                report's cpu_seconds, best of REPEATS processes), the same
//                run in this process as the command makes it (samples to a
//                sink, steps to the drift monitor) and bare (sim::simulate,
//                samples kept), Boost.Odeint's
//                dopri5 and rkf78 (controlled, best of REPEATS), each run in
//                a process of its own as the command is (this program run
//                again with --peer-run) and, warm, in this process, over a
//                sweep of tolerances; the error |dOmega| + |dgamma| at T against the
//                Richardson-extrapolated Gauss6 reference of `epviz bench`
//                (study/reference.hpp); the CPU time at errors 1e-8 and 1e-10
//                by log-log interpolation, and the ratios;
//   rk4 step     the command's RK4 per step (h = 1e-3, T = 300), against a
//                plain RK4 loop written out here on the same equations;
//   memory       1e7 RK4 steps written as one sample and as 1,000 samples:
//                the process's peak resident memory and CPU time (wait4).
//
//   epviz_simulate_bench [REPEATS]        (default 5)
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "physics/cases.hpp"
#include "sim/drift.hpp"
#include "sim/simulate.hpp"
#include "study/peers/peers.hpp"
#include "study/reference.hpp"

namespace {

namespace fs = std::filesystem;
using namespace epviz;

constexpr double kTEnd = 300.0;

struct ProcessRun {
  double cpu = 0.0;  // user + system of the child
  long max_rss_kb = 0;
  nlohmann::json report;
  sim::Sample last;
};

// Runs epviz with `args` (its report to `dir`/report.json, its samples to
// `dir`/samples.csv) and waits for it with wait4, for its resources.
ProcessRun run_epviz(const std::vector<std::string>& args, const fs::path& dir, bool read_csv) {
  const fs::path report = dir / "report.json", csv = dir / "samples.csv";
  // EPVIZ_SIMULATE_BINARY: another build's epviz, to compare two commits on
  // one machine in one run (docs/benchmarks.md).
  const char* other = std::getenv("EPVIZ_SIMULATE_BINARY");
  std::vector<std::string> all{other && *other ? other : EPVIZ_BINARY, "simulate"};
  all.insert(all.end(), args.begin(), args.end());
  all.insert(all.end(), {"--report-json", report.string()});
  if (read_csv) all.insert(all.end(), {"--csv", csv.string()});
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);  // or the child's copy of the buffer is printed again
  const pid_t pid = fork();
  if (pid == 0) {
    if (!freopen("/dev/null", "w", stdout)) _exit(126);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage ru{};
  if (pid < 0 || wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "epviz_simulate_bench: epviz simulate failed (status %d)\n", status);
    std::exit(1);
  }
  ProcessRun r;
  r.cpu = double(ru.ru_utime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec) +
          double(ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_stime.tv_usec);
  r.max_rss_kb = ru.ru_maxrss;
  std::ifstream(report) >> r.report;
  if (read_csv) {
    std::ifstream in(csv);
    std::string line, last;
    while (std::getline(in, line))
      if (!line.empty()) last = line;
    std::stringstream fields(last);
    std::array<double, 7> v{};
    for (double& x : v) {
      std::string cell;
      std::getline(fields, cell, ',');
      x = std::stod(cell);
    }
    r.last.t = v[0];
    r.last.omega = {v[1], v[2], v[3]};
    r.last.gamma = {v[4], v[5], v[6]};
  }
  return r;
}

std::string tol_text(double tol) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", tol);
  return buf;
}

// One point of a work-precision curve.
struct Point {
  double error = 0.0;
  double cpu = 0.0;
};

// CPU time at `error` by log-log interpolation between the two points of the
// curve that bracket it; NaN when none does.
double cpu_at(std::vector<Point> curve, double error) {
  std::sort(curve.begin(), curve.end(), [](auto& a, auto& b) { return a.error < b.error; });
  for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
    const Point& a = curve[i];
    const Point& b = curve[i + 1];
    if (a.error <= error && error <= b.error && a.error > 0.0 && b.error > a.error) {
      const double s = std::log(error / a.error) / std::log(b.error / a.error);
      return std::exp(std::log(a.cpu) + s * (std::log(b.cpu) - std::log(a.cpu)));
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// The run every process of the comparison makes: the preset at tol, DOP853
// for the command (the peers take only body, state, tol and t_end from it).
sim::RunSpec preset_spec(double tol) {
  sim::RunSpec spec = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                                      sim::Formulation::direct, kTEnd, 1);
  spec.tol = tol;
  return spec;
}

// This program started again as `--peer-run ID TOL`: one peer's run, alone in
// a fresh process as `epviz simulate`'s is (its first run pays for the cold
// caches and the page faults the command pays for), its result on stdout.
int peer_run_child(int id, double tol) {
  const auto r = study::peers::run_peer(static_cast<study::peers::PeerId>(id), preset_spec(tol), 1);
  std::printf("%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", r.ok() ? 1 : 0, r.cpu_seconds,
              r.t, r.omega[0], r.omega[1], r.omega[2], r.gamma[0], r.gamma[1], r.gamma[2]);
  return 0;
}

// A peer's run in a process of its own (this program with --peer-run).
study::peers::PeerResult peer_in_own_process(study::peers::PeerId id, double tol) {
  int fds[2];
  if (pipe(fds) != 0) {
    std::perror("epviz_simulate_bench: pipe");
    std::exit(1);
  }
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  std::string id_text = std::to_string(static_cast<int>(id)), tol_arg = tol_text(tol);
  std::string flag = "--peer-run", self_arg = self;
  char* argv[] = {self_arg.data(), flag.data(), id_text.data(), tol_arg.data(), nullptr};
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(fds[1], STDOUT_FILENO);
    close(fds[0]);
    close(fds[1]);
    execv(argv[0], argv);
    _exit(127);
  }
  close(fds[1]);
  std::string text;
  char buf[512];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) text.append(buf, std::size_t(n));
  close(fds[0]);
  int status = 0;
  study::peers::PeerResult r;
  std::istringstream in(text);
  int ok = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
      !(in >> ok >> r.cpu_seconds >> r.t >> r.omega[0] >> r.omega[1] >> r.omega[2] >> r.gamma[0] >>
        r.gamma[1] >> r.gamma[2])) {
    std::fprintf(stderr, "epviz_simulate_bench: the peer's own process failed (status %d)\n",
                 status);
    std::exit(1);
  }
  if (!ok) r.status = study::peers::PeerStatus::failed;
  return r;
}

sim::Sample sample_of(const study::peers::PeerResult& r) {
  sim::Sample s;
  s.t = r.t;
  s.omega = r.omega;
  s.gamma = r.gamma;
  return s;
}

// The direct equations (math.md eqs. 1.1-1.2) and a classical RK4 step,
// written out on plain arrays: what an RK4 step costs with nothing around it.
struct PlainTop {
  double inertia[3], pr[3];
  void rhs(const double x[6], double d[6]) const {
    const double w0 = x[0], w1 = x[1], w2 = x[2], g0 = x[3], g1 = x[4], g2 = x[5];
    d[0] = ((inertia[1] - inertia[2]) * w1 * w2 + g1 * pr[2] - g2 * pr[1]) / inertia[0];
    d[1] = ((inertia[2] - inertia[0]) * w2 * w0 + g2 * pr[0] - g0 * pr[2]) / inertia[1];
    d[2] = ((inertia[0] - inertia[1]) * w0 * w1 + g0 * pr[1] - g1 * pr[0]) / inertia[2];
    d[3] = w2 * g1 - w1 * g2;
    d[4] = w0 * g2 - w2 * g0;
    d[5] = w1 * g0 - w0 * g1;
  }
  void step(double x[6], double h) const {
    double k1[6], k2[6], k3[6], k4[6], y[6];
    rhs(x, k1);
    for (int i = 0; i < 6; ++i) y[i] = x[i] + 0.5 * h * k1[i];
    rhs(y, k2);
    for (int i = 0; i < 6; ++i) y[i] = x[i] + 0.5 * h * k2[i];
    rhs(y, k3);
    for (int i = 0; i < 6; ++i) y[i] = x[i] + h * k3[i];
    rhs(y, k4);
    for (int i = 0; i < 6; ++i) x[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }
};

double plain_rk4_seconds_per_step(const physics::Body& body, const physics::InitialState& s0,
                                  long steps, double h, int repeats) {
  PlainTop top{};
  for (int i = 0; i < 3; ++i) {
    top.inertia[i] = body.inertia[i];
    top.pr[i] = body.weight * body.com[i];
  }
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeats; ++r) {
    double x[6] = {s0.omega[0], s0.omega[1], s0.omega[2], s0.gamma[0], s0.gamma[1], s0.gamma[2]};
    const double start = sim::thread_cpu_seconds();
    for (long k = 0; k < steps; ++k) top.step(x, h);
    const double cpu = sim::thread_cpu_seconds() - start;
    // The state is used, so that the loop is not optimised away.
    if (!std::isfinite(x[0] + x[3])) std::fprintf(stderr, "plain rk4 lost the motion\n");
    best = std::min(best, cpu);
  }
  return best / double(steps);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == "--peer-run")
    return peer_run_child(std::atoi(argv[2]), std::atof(argv[3]));
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const fs::path dir =
      fs::temp_directory_path() / ("epviz_simulate_bench." + std::to_string(getpid()));
  fs::create_directories(dir);
  const auto& preset = physics::preset(physics::Case::kovalevskaya);

  std::printf("epviz simulate as a process, Kovalevskaya preset, T = %g, best of %d\n", kTEnd,
              repeats);
  const auto reference = study::compute_reference(preset.body, preset.initial, kTEnd, 1,
                                                  study::reference_step(preset.initial));
  const sim::Sample& ref = reference.samples.back();
  std::printf(
      "reference: Richardson Gauss6 (h = %.3g), self-check against DOP853 at 1e-14: %.2g\n\n",
      reference.step, reference.self_check);

  const std::vector<double> tolerances{1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14};
  // The peers' times: each run in a process of its own, as the command's
  // (the comparison the targets are set on), and warm in this process.
  std::vector<Point> process, in_process, dopri5, rkf78, dopri5_warm, rkf78_warm;
  std::printf("%-8s %-10s %-11s %-11s %-11s %-6s %-10s %-10s %-10s %-10s %-10s %-10s\n", "tol",
              "error", "epviz cpu s", "observed s", "stepper s", "steps", "dopri5 err", "dopri5 s",
              "(warm)", "rkf78 err", "rkf78 s", "(warm)");
  for (double tol : tolerances) {
    ProcessRun best;
    best.cpu = std::numeric_limits<double>::infinity();
    double best_reported = std::numeric_limits<double>::infinity();
    for (int r = 0; r < repeats; ++r) {
      auto run = run_epviz({"--case", "kovalevskaya", "--method", "dop853", "--tol", tol_text(tol),
                            "--t-end", "300", "--samples", "1"},
                           dir, true);
      const double reported = run.report.at("cpu_seconds").get<double>();
      if (reported < best_reported) {
        best_reported = reported;
        best = std::move(run);
      }
    }
    const double error = study::state_error(best.last, ref);
    process.push_back({error, best_reported});

    const sim::RunSpec spec = preset_spec(tol);
    double alone = std::numeric_limits<double>::infinity();
    for (int r = 0; r < repeats; ++r) alone = std::min(alone, sim::simulate(spec).cpu_seconds);
    in_process.push_back({error, alone});
    // As the command runs it, in this process: samples to a sink, every step
    // to the drift monitor; the rest of the command's time is its process's
    // first run (page faults, cold caches).
    double observed = std::numeric_limits<double>::infinity();
    for (int r = 0; r < repeats; ++r) {
      sim::RunDriftMonitor drifts(spec);
      const auto result = sim::simulate(
          spec, [&](const sim::Sample& s) { drifts.output(s); },
          [&](const sim::Sample& s) { drifts.step(s); });
      observed = std::min(observed, result.cpu_seconds);
    }

    // Best of `repeats` runs, each in its own process (own) or here (warm).
    auto peer = [&](study::peers::PeerId id, std::vector<Point>& curve, std::vector<Point>& warm) {
      double cpu = std::numeric_limits<double>::infinity(), cpu_warm = cpu;
      study::peers::PeerResult last;
      for (int r = 0; r < repeats; ++r) {
        last = peer_in_own_process(id, tol);
        cpu = std::min(cpu, last.cpu_seconds);
        cpu_warm = std::min(cpu_warm, study::peers::run_peer(id, spec, 1).cpu_seconds);
      }
      const double e = last.ok() ? study::state_error(sample_of(last), ref) : NAN;
      if (last.ok()) {
        curve.push_back({e, cpu});
        warm.push_back({e, cpu_warm});
      }
      return std::tuple{e, cpu, cpu_warm};
    };
    const auto [e5, c5, w5] =
        peer(study::peers::PeerId::odeint_dopri5_controlled, dopri5, dopri5_warm);
    const auto [e78, c78, w78] =
        peer(study::peers::PeerId::odeint_rkf78_controlled, rkf78, rkf78_warm);
    std::printf(
        "%-8g %-10.3g %-11.3g %-11.3g %-11.3g %-6ld %-10.3g %-10.3g %-10.3g %-10.3g %-10.3g "
        "%-10.3g\n",
        tol, error, best_reported, observed, alone, best.report.at("steps").get<long>(), e5, c5, w5,
        e78, c78, w78);
  }

  std::printf(
      "\nat equal error (log-log interpolation; ratio = faster Boost / epviz simulate, every run "
      "in a process of its own; warm: the stepper and Boost in this process):\n");
  for (double e : {1e-8, 1e-10}) {
    const double ep = cpu_at(process, e), ei = cpu_at(in_process, e);
    const double d5 = cpu_at(dopri5, e), d78 = cpu_at(rkf78, e);
    const double w5 = cpu_at(dopri5_warm, e), w78 = cpu_at(rkf78_warm, e);
    const double boost = std::fmin(d5, d78), boost_warm = std::fmin(w5, w78);
    std::printf(
        "  error %g: epviz simulate %.3g s, odeint dopri5 %.3g s, rkf78 %.3g s: epviz %.2fx faster "
        "than the faster Boost\n"
        "    warm: stepper %.3g s (command / stepper %.2f), dopri5 %.3g s, rkf78 %.3g s: "
        "stepper %.2fx faster than the faster Boost\n",
        e, ep, d5, d78, boost / ep, ei, ep / ei, w5, w78, boost_warm / ei);
  }

  // RK4 per step: the command against a plain loop.
  {
    const double h = 1e-3;
    const long steps = std::lround(kTEnd / h);
    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r < repeats; ++r) {
      const auto run = run_epviz({"--case", "kovalevskaya", "--method", "rk4", "--step", "0.001",
                                  "--t-end", "300", "--samples", "1000"},
                                 dir, false);
      best = std::min(best, run.report.at("cpu_seconds").get<double>());
    }
    const double plain = plain_rk4_seconds_per_step(preset.body, preset.initial, steps, h, repeats);
    std::printf("\nrk4, %ld steps: epviz simulate %.1f ns a step, plain loop %.1f ns: %.2fx\n",
                steps, 1e9 * best / double(steps), 1e9 * plain, best / double(steps) / plain);
  }

  // Memory and CPU against the steps between two samples.
  {
    std::printf("\n1e7 rk4 steps (generic preset, h = 1e-5, T = 100), as processes:\n");
    double cpu[2] = {0, 0};
    long rss[2] = {0, 0};
    const char* samples[2] = {"1", "1000"};
    for (int k = 0; k < 2; ++k) {
      cpu[k] = std::numeric_limits<double>::infinity();
      for (int r = 0; r < std::min(repeats, 3); ++r) {
        const auto run = run_epviz({"--case", "generic", "--method", "rk4", "--step", "1e-5",
                                    "--t-end", "100", "--samples", samples[k]},
                                   dir, false);
        cpu[k] = std::min(cpu[k], run.cpu);
        rss[k] = std::max(rss[k], run.max_rss_kb);
      }
      std::printf("  --samples %-5s peak resident %6.1f MB, CPU %.2f s (best)\n", samples[k],
                  double(rss[k]) / 1024.0, cpu[k]);
    }
    std::printf("  one sample / 1000 samples: memory %.2fx, CPU %.2fx\n",
                double(rss[0]) / double(rss[1]), cpu[0] / cpu[1]);
  }
  fs::remove_all(dir);
  return 0;
}
