#pragma once
// A Poincaré section's orbits, run independently on a pool of threads: the
// dop853 orbits side by side in the lanes of the batch integrator
// (sim::section_crossings_batched), the others one at a time.
#include <optional>
#include <string>
#include <vector>

#include "numerics/failure.hpp"
#include "section/section_job.hpp"
#include "shard/shard_spec.hpp"
#include "sim/section.hpp"

namespace epviz::section {

struct OrbitResult {
  int orbit = 0;           // 1, 2, ... in the order of the starts
  std::size_t method = 0;  // index into job.methods
  physics::InitialState start;
  std::vector<sim::Crossing> crossings;
  std::optional<numerics::Failure> failure;  // a lost orbit: its crossings are not results
};

// `requested` threads, or all cores for 0.
int thread_count(long requested);

// Every method with every start: job.methods.size() x starts.size().
long run_count(const SectionJob& job, std::size_t starts);

// One result per run (section_run_of) of `runs` (default: all), in their
// order, computed by `threads` threads (at least 1); an orbit's numerical
// failure ends that orbit only. The crossings are bitwise those of
// sim::section_crossings run on each orbit alone, whichever path takes it.
// With `batched` false every orbit takes the scalar path (for comparisons).
// Throws io::BadInput, before any orbit runs, for an EPVIZ_SIMD naming no
// path of this CPU when some orbit would take the batch.
std::vector<OrbitResult> run_section(const SectionJob& job,
                                     const std::vector<physics::InitialState>& starts, int threads,
                                     std::optional<shard::ItemRange> runs = std::nullopt,
                                     bool batched = true);

// The failed orbits, one line: how many, and the first one's orbit number,
// start (and method, when there are several) and failure ("orbit 3 from omega
// ..., gamma ...: dop853 failed at t = ...:
// ...; what to change in the section file, by the failure and the method").
// Empty when every orbit kept the motion.
std::string lost_orbits_line(const SectionJob& job, const std::vector<OrbitResult>& results);

// "16 orbits, 6400 crossings" (`starts` orbits, the crossings of `results`),
// for a level with fewer states than asked "13 orbits (3 of 16 directions of
// gamma lie below the level), ...", with several methods "16 orbits x 3 methods, ...".
std::string summary(const SectionJob& job, std::size_t starts,
                    const std::vector<OrbitResult>& results);

}  // namespace epviz::section
