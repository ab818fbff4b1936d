// What a Poincaré section costs against the integration under it, in one run:
// the orbits of the shipped generic section's level (render_jobs/
// generic.section.json: its level, surface, method and tolerance), each run
// four ways on the same threads —
//   bare       the DOP853 stepper stepping to the orbit's last crossing and
//              no further: the integration alone
//   section    section::run_section on the scalar path: every step checked
//              for a sign change, each crossing located on the dense output,
//              checked and kept
//   batch      the same bare integration by the SIMD batch integrator
//              (sim/ensemble.hpp)
//   section on the batch
//              section::run_section as `epviz section` runs it: the same
//              section, its orbits in the batch integrator's lanes (checked
//              to give the scalar section's crossings)
// Each is timed twice, in turn, and the round with less CPU time is kept
// (other load on the machine only slows a round). Then `epviz section` runs
// the same section once as a process, writing the CSV of every crossing (its
// figures are left out: docs/benchmarks.md times them). It prints wall and
// CPU seconds of each, the CPU cost per crossing and the section's ratio to
// the bare integration.
//
//   epviz_section_bench [ORBITS] [CROSSINGS] [THREADS]   (default 1024 1000 0: all cores)
#include <sys/resource.h>
#include <unistd.h>

#include <ctime>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/subprocess.hpp"
#include "numerics/embedded_rk.hpp"
#include "numerics/simd_path.hpp"
#include "physics/direct.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"
#include "sim/ensemble.hpp"

namespace {

using namespace epviz;
using Clock = std::chrono::steady_clock;

struct Timing {
  double wall = 0.0, cpu = 0.0;  // cpu: every thread of the process
};

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

template <class F>
Timing timed(F&& f) {
  const auto w0 = Clock::now();
  const double c0 = process_cpu_seconds();
  f();
  return {std::chrono::duration<double>(Clock::now() - w0).count(), process_cpu_seconds() - c0};
}

double children_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  auto s = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return s(u.ru_utime) + s(u.ru_stime);
}

// The first three fields of /proc/loadavg: how busy the machine was.
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

Timing better(const Timing& a, const Timing& b) { return a.cpu <= b.cpu ? a : b; }

// Each orbit from its start to `t_end[i]` with the section's stepper and
// options (sim/section.cpp), nothing else; the orbits shared among `threads`
// threads as run_section shares them. Returns the steps taken.
numerics::AdaptiveOptions options_of(const section::SectionJob& job) {
  numerics::AdaptiveOptions opts;
  opts.rtol = job.methods[0].tol;
  opts.atol = job.methods[0].tol;
  return opts;
}

long bare_integration(const section::SectionJob& job,
                      const std::vector<physics::InitialState>& starts,
                      const std::vector<double>& t_end, int threads) {
  const numerics::AdaptiveOptions opts = options_of(job);
  const physics::DirectSystem sys(job.body);
  std::atomic<std::size_t> next{0};
  std::atomic<long> steps{0};
  auto work = [&] {
    long mine = 0;
    for (std::size_t i = next++; i < starts.size(); i = next++) {
      numerics::Dop853<physics::DirectSystem> stepper(sys, opts);
      stepper.init(0.0, physics::DirectSystem::pack(starts[i]));
      while (stepper.t() < t_end[i]) {
        stepper.step();
        ++mine;
      }
    }
    steps += mine;
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  return steps;
}

void batch_integration(const section::SectionJob& job,
                       const std::vector<physics::InitialState>& starts,
                       const std::vector<double>& t_end, int threads) {
  std::vector<sim::DirectBatchTask> tasks;
  for (std::size_t i = 0; i < starts.size(); ++i)
    tasks.push_back(sim::direct_batch_task(starts[i], t_end[i]));
  sim::DirectBatchSettings settings;
  settings.adaptive = options_of(job);
  for (const auto& r : sim::integrate_direct_batch_parallel(job.body, tasks, settings, threads))
    if (r.failure) {
      std::fprintf(stderr, "epviz_section_bench: a batch trajectory failed\n");
      std::exit(1);
    }
}

// `epviz section` on the shipped generic section with `orbits`, `crossings`
// and `threads`, writing only its CSV.
Timing section_command(int orbits, int crossings, int threads) {
  namespace fs = std::filesystem;
  std::string name = "epviz-section-bench-";
  name += std::to_string(::getpid());
  const fs::path dir = fs::temp_directory_path() / name;
  fs::create_directories(dir);
  auto spec =
      nlohmann::json::parse(std::ifstream(EPVIZ_SOURCE_DIR "/render_jobs/generic.section.json"));
  spec.erase("png");
  spec.erase("svg");
  spec["orbits"] = orbits;
  spec["crossings"] = crossings;
  spec["t_end"] = 1e9;
  spec["csv"] = (dir / "crossings.csv").string();
  std::ofstream(dir / "bench.section.json") << spec.dump();
  const double c0 = children_cpu_seconds();
  const auto w0 = Clock::now();
  const auto r = io::run_process({EPVIZ_BINARY, "section", (dir / "bench.section.json").string(),
                                  "-j", std::to_string(threads)});
  const Timing t{std::chrono::duration<double>(Clock::now() - w0).count(),
                 children_cpu_seconds() - c0};
  fs::remove_all(dir);
  if (!r.status.success()) {
    std::fprintf(stderr, "epviz section %s: %s\n", r.status.describe().c_str(), r.err.c_str());
    std::exit(1);
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const int orbits = argc > 1 ? std::atoi(argv[1]) : 1024;
  const int crossings = argc > 2 ? std::atoi(argv[2]) : 1000;
  const int threads = section::thread_count(argc > 3 ? std::atol(argv[3]) : 0);
  if (orbits < 1 || crossings < 1) {
    std::fprintf(stderr, "epviz_section_bench: ORBITS and CROSSINGS must be positive integers\n");
    return 2;
  }
  auto job = section::read_section_job(EPVIZ_SOURCE_DIR "/render_jobs/generic.section.json");
  job.orbits = orbits;
  job.crossings = crossings;
  job.t_end = 1e9;  // every orbit runs to its crossings
  const auto starts = section::section_starts(job);
  const std::string load_before = load_average();

  std::vector<section::OrbitResult> results, batch_results;
  auto run_section = [&] {
    results = section::run_section(job, starts, threads, std::nullopt, false);
  };
  auto run_batch_section = [&] { batch_results = section::run_section(job, starts, threads); };
  // The orbits' last crossings, known after a first section: the bare
  // integration runs to the same times.
  run_section();
  std::vector<double> t_end;
  long found = 0;
  for (const auto& r : results) {
    if (r.failure) {
      std::fprintf(stderr, "epviz_section_bench: %s\n",
                   section::lost_orbits_line(job, results).c_str());
      return 1;
    }
    t_end.push_back(r.crossings.empty() ? job.t_end : r.crossings.back().t);
    found += long(r.crossings.size());
  }
  long steps = 0;
  const Timing bare1 = timed([&] { steps = bare_integration(job, starts, t_end, threads); });
  const Timing sec1 = timed(run_section);
  const Timing batch1 = timed([&] { batch_integration(job, starts, t_end, threads); });
  const Timing bsec1 = timed(run_batch_section);
  const Timing bare2 = timed([&] { bare_integration(job, starts, t_end, threads); });
  const Timing sec2 = timed(run_section);
  const Timing batch2 = timed([&] { batch_integration(job, starts, t_end, threads); });
  const Timing bsec2 = timed(run_batch_section);
  const Timing bare = better(bare1, bare2), sec = better(sec1, sec2),
               batch = better(batch1, batch2), bsec = better(bsec1, bsec2);
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto &a = results[i].crossings, &b = batch_results[i].crossings;
    bool same = a.size() == b.size() && !batch_results[i].failure;
    for (std::size_t k = 0; same && k < a.size(); ++k)
      same = a[k].t == b[k].t && a[k].omega == b[k].omega && a[k].gamma == b[k].gamma;
    if (!same) {
      std::fprintf(stderr, "epviz_section_bench: orbit %zu differs on the batch\n", i + 1);
      return 1;
    }
  }
  const Timing command = section_command(orbits, crossings, threads);

  double time_sum = 0.0;
  for (double t : t_end) time_sum += t;
  std::printf("generic body, level C1 = %g, C0 = %g; section %s = %g %s; %s\n", job.level->energy,
              job.level->area, sim::name(job.surface.function).data(), job.surface.value,
              sim::name(job.surface.direction).data(),
              section::method_label(job.methods[0]).c_str());
  std::printf(
      "%zu orbits (of %d asked), %ld crossings, mean T %.1f, %.1f steps per crossing, %d threads\n",
      starts.size(), orbits, found, time_sum / double(starts.size()), double(steps) / double(found),
      threads);
  auto line = [&](const char* name, const Timing& t) {
    std::printf("%-22s wall %7.2f s  cpu %7.2f s  %6.2f us cpu per crossing  %5.2fx bare\n", name,
                t.wall, t.cpu, 1e6 * t.cpu / double(found), t.cpu / bare.cpu);
  };
  line("bare", bare);
  line("section", sec);
  line("batch (SIMD), bare", batch);
  line("section on the batch", bsec);
  line("epviz section, CSV", command);
  std::printf(
      "section / bare: %.3f (cpu), %.3f (wall); cpu of the rounds: bare %.2f, %.2f s, "
      "section %.2f, %.2f s\n",
      sec.cpu / bare.cpu, sec.wall / bare.wall, bare1.cpu, bare2.cpu, sec1.cpu, sec2.cpu);
  std::printf(
      "section on the batch: %.3f of the bare batch, %.3f of the scalar section (cpu); "
      "cpu of the rounds: batch %.2f, %.2f s, section on the batch %.2f, %.2f s; path %s\n",
      bsec.cpu / batch.cpu, bsec.cpu / sec.cpu, batch1.cpu, batch2.cpu, bsec1.cpu, bsec2.cpu,
      numerics::simd_path_report().c_str());
  std::printf("load average before: %s, after: %s\n", load_before.c_str(), load_average().c_str());
  return 0;
}
