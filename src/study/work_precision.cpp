#include "study/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "study/reference.hpp"
#include "study/sweeps.hpp"
#include "study/timed_run.hpp"

namespace epviz::study {

// Final times: 10 time units, except the chaotic generic body (5: its
// largest Lyapunov exponent amplifies errors so fast that beyond ~10 time
// units every error saturates at O(1) and the chart says nothing).
double wp_t_end(physics::Case c) { return c == physics::Case::generic ? 5.0 : 10.0; }

double wp_t_end(const Problem& p) { return std::isfinite(p.t_end) ? p.t_end : wp_t_end(p.id); }

std::vector<StudyRow> work_precision_study(const StudyOptions& o) {
  std::vector<StudyRow> rows;
  const int repeats = repeats_of(o);
  const std::vector<double> tols =
      o.quick ? std::vector<double>{1e-4, 1e-6, 1e-8, 1e-10, 1e-12}
              : std::vector<double>{1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  const int max_points = o.quick ? 5 : 8;
  const long cost_cap = o.quick ? 400'000 : 4'000'000;
  for (const auto& p : problems_of(o)) {
    const double t_end = wp_t_end(p);
    tell(o, "work-precision: reference for " + p.name);
    const auto ref = compute_reference(p.body, p.initial, t_end, 1, reference_step(p.initial));
    const sim::Sample& ref_end = ref.samples.back();
    const double period = fastest_period(p.initial);
    std::vector<WorkPrecisionRow> runs;
    for (const auto f : formulations_of(o)) {
      for (const auto m : methods_of(o)) {
        if (sim::incompatibility(m, f)) continue;
        tell(o, "work-precision: " + p.name + " " + std::string(sim::name(f)) + " " +
                    std::string(sim::name(m)));
        auto one = [&](const sim::RunSpec& spec) {
          const auto t = timed_run(spec, repeats);
          WorkPrecisionRow row{run_record(spec, t)};
          const auto& r = t.result;
          if (!r.failure && !r.samples.empty() && finite(r.samples.back()) &&
              r.samples.back().t == ref_end.t)
            row.error = state_error(r.samples.back(), ref_end);
          runs.push_back(row);
          return std::pair{row.error, t.cost};
        };
        auto spec = problem_run(p, m, f, t_end, 1);
        if (sim::is_adaptive(m)) {
          for (const double tol : tols) {
            spec.tol = tol;
            one(spec);
          }
        } else {
          long n = first_steps(t_end, period, 1.0 / 8.0);
          const int j = halvings_per_point(sim::order(m));
          for (int k = 0; k < max_points; ++k, n <<= j) {
            spec.step = t_end / double(n);
            const auto [err, cost] = one(spec);
            // Stop at round-off level, or when the next point would cost too much.
            if (std::isfinite(err) && err < 1e-11) break;
            if (double(cost) * double(1L << j) > double(cost_cap)) break;
          }
        }
      }
    }
    // Errors within 10x the references' disagreement are not resolved by them:
    // flagged, and left out of smallest_error.
    double smallest = std::numeric_limits<double>::infinity();
    double smallest_any = smallest;
    for (auto& row : runs) {
      const double e = row.error;
      row.error_resolved = std::isfinite(e) && e > 10.0 * ref.self_check;
      if (std::isfinite(e)) smallest_any = std::min(smallest_any, e);
      if (row.error_resolved) smallest = std::min(smallest, e);
      rows.emplace_back(std::move(row));
    }
    ReferenceRow r;
    r.case_name = p.name;
    r.t_end = t_end;
    r.step = ref.step;
    r.self_check = ref.self_check;
    r.smallest_error = std::isfinite(smallest) ? smallest : kNaN;
    r.smallest_error_any = std::isfinite(smallest_any) ? smallest_any : kNaN;
    r.cpu_ms = 1e3 * ref.cpu_seconds;
    rows.emplace_back(std::move(r));
  }
  return rows;
}

}  // namespace epviz::study
