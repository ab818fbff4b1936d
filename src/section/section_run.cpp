#include "section/section_run.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>

#include "io/bad_input.hpp"
#include "numerics/simd_path.hpp"
#include "physics/format.hpp"
#include "sim/run_spec.hpp"

namespace epviz::section {
namespace {

sim::RunSpec orbit_run(const SectionJob& job, const SectionMethod& m,
                       const physics::InitialState& start) {
  sim::RunSpec run;
  run.case_id = job.case_id;
  run.body = job.body;
  run.initial = start;
  run.method = m.method;
  run.tol = m.tol;
  run.step = m.step;
  run.t_end = job.t_end;
  run.max_drift = job.max_drift;
  return run;
}

// What to change in the section file for a lost orbit: by what went wrong,
// and by whether the method chose its steps by "tol" or took "step".
std::string lost_orbit_advice(numerics::FailureKind kind, bool adaptive) {
  using numerics::FailureKind;
  const std::string drift = ", or raise \"max_drift\" if the drift is expected";
  switch (kind) {
    case FailureKind::step_budget:
      // Sections have no key for the budget: the run itself must be shorter.
      return std::string(
                 "the run needs more steps than one run may take: shorten it (a smaller "
                 "\"t_end\", fewer \"crossings\")") +
             (adaptive ? ", or loosen \"tol\"" : ", or use a larger \"step\"");
    case FailureKind::step_underflow: return adaptive ? "loosen \"tol\"" : "use a larger \"step\"";
    case FailureKind::rejections: return adaptive ? "loosen \"tol\"" : "use a smaller \"step\"";
    case FailureKind::chart_pole: return "use another \"method\"";
    case FailureKind::non_finite:
    case FailureKind::solver_divergence:
    case FailureKind::lost_motion: break;
  }
  return adaptive ? "tighten \"tol\"" + drift
                  : "use a smaller \"step\" or an adaptive \"method\" (dop853)" + drift;
}

}  // namespace

int thread_count(long requested) {
  return requested > 0 ? int(requested) : int(std::max(1u, std::thread::hardware_concurrency()));
}

long run_count(const SectionJob& job, std::size_t starts) {
  return long(job.methods.size() * starts);
}

std::vector<OrbitResult> run_section(const SectionJob& job,
                                     const std::vector<physics::InitialState>& starts, int threads,
                                     std::optional<shard::ItemRange> runs, bool batched) {
  const shard::ItemRange range = runs.value_or(shard::ItemRange{0, run_count(job, starts.size())});
  std::vector<OrbitResult> results(std::size_t(range.size()));
  std::vector<sim::RunSpec> specs(results.size());
  for (std::size_t i = 0; i < results.size(); ++i) {
    const SectionRun run = section_run_of(range.first + long(i), starts.size());
    OrbitResult& r = results[i];
    r.orbit = int(run.start) + 1;
    r.method = run.method;
    r.start = starts[run.start];
    specs[i] = orbit_run(job, job.methods[run.method], r.start);
  }
  const int n = std::max(1, std::min<int>(threads, int(results.size())));
  const auto on_batch = [&](std::size_t i) { return batched && sim::sections_batched(specs[i]); };
  // EPVIZ_SIMD is input: refused as bad input before any orbit runs.
  for (std::size_t i = 0; i < results.size(); ++i)
    if (on_batch(i)) {
      try {
        numerics::chosen_simd_path();
      } catch (const std::invalid_argument& e) {
        throw io::BadInput(e.what());
      }
      break;
    }

  // The batched orbits first, method by method (one body, tolerance and step
  // budget each), every thread running batches of them.
  for (std::size_t m = 0; m < job.methods.size(); ++m) {
    std::vector<std::size_t> mine;
    std::vector<sim::RunSpec> batch;
    for (std::size_t i = 0; i < results.size(); ++i)
      if (results[i].method == m && on_batch(i)) {
        mine.push_back(i);
        batch.push_back(specs[i]);
      }
    if (batch.empty()) continue;
    auto found = sim::section_crossings_batched(batch, job.surface, job.crossings, n);
    for (std::size_t k = 0; k < mine.size(); ++k) {
      results[mine[k]].crossings = std::move(found[k].crossings);
      results[mine[k]].failure = std::move(found[k].failure);
    }
  }

  // Then the others, one orbit at a time. Orbits differ in cost (a slow
  // crossing rate means a long run), so each thread takes the next orbit not
  // yet taken rather than a fixed share.
  std::vector<std::size_t> scalar;
  for (std::size_t i = 0; i < results.size(); ++i)
    if (!on_batch(i)) scalar.push_back(i);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k = next++; k < scalar.size(); k = next++) {
      OrbitResult& r = results[scalar[k]];
      try {
        r.crossings = sim::section_crossings(specs[scalar[k]], job.surface, job.crossings);
      } catch (const numerics::IntegrationError& e) {
        r.failure = e.failure();
        r.crossings.clear();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min<int>(n, int(scalar.size())); ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  return results;
}

std::string summary(const SectionJob& job, std::size_t starts,
                    const std::vector<OrbitResult>& results) {
  long crossings = 0;
  for (const auto& r : results) crossings += long(r.crossings.size());
  std::string s = std::to_string(starts);
  s += " orbits";
  if (job.level && std::size_t(job.orbits) > starts) {
    s += " (";
    s += std::to_string(std::size_t(job.orbits) - starts);
    s += " of ";
    s += std::to_string(job.orbits);
    s += " directions of gamma lie below the level)";
  }
  if (job.methods.size() > 1) {
    s += " x ";
    s += std::to_string(job.methods.size());
    s += " methods";
  }
  s += ", ";
  s += std::to_string(crossings);
  s += " crossings";
  return s;
}

std::string lost_orbits_line(const SectionJob& job, const std::vector<OrbitResult>& results) {
  const OrbitResult* first = nullptr;
  long lost = 0;
  for (const auto& r : results)
    if (r.failure) {
      if (!first) first = &r;
      ++lost;
    }
  if (!first) return {};
  std::string line = std::to_string(lost);
  line += " of ";
  line += std::to_string(results.size());
  line += " orbits lost, the first: orbit ";
  line += std::to_string(first->orbit);
  if (job.methods.size() > 1) {
    line += " (";
    line += method_label(job.methods[first->method]);
    line += ")";
  }
  line += " from omega ";
  line += physics::detail::vec(first->start.omega);
  line += ", gamma ";
  line += physics::detail::vec(first->start.gamma);
  line += ": ";
  line += first->failure->message();
  line += "; ";
  line +=
      lost_orbit_advice(first->failure->kind, sim::is_adaptive(job.methods[first->method].method));
  return line;
}

}  // namespace epviz::section
