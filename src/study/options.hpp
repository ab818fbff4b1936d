#pragma once
// What a bench run asks of the studies, and the defaults they fill in.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "physics/cases.hpp"
#include "sim/run_spec.hpp"

namespace epviz::study {

// A body and its initial state to study: a preset, or a custom body (from a
// render or simulate job).
struct Problem {
  physics::Case id = physics::Case::custom;
  std::string name;  // the rows' case name: the preset's, or "custom"
  physics::Body body;
  physics::InitialState initial;
  // A job's final time, which its work-precision runs reach; NaN: the
  // study's own for the case (study::wp_t_end).
  double t_end = std::numeric_limits<double>::quiet_NaN();
};

struct StudyOptions {
  bool quick = false;
  std::vector<physics::Case> cases;  // presets; empty = all six (none when `custom` is given)
  std::optional<Problem> custom;     // a body of one's own for the work-precision study
  std::vector<sim::Method> methods;  // empty = sim::all_methods()
  std::vector<sim::Formulation> formulations;        // empty = sim::all_formulations()
  int repeats = 0;                                   // CPU-time repeats; 0 = 3 (quick) or 5 (full)
  std::function<void(const std::string&)> progress;  // optional: told what runs next
};

const std::vector<sim::Method>& methods_of(const StudyOptions& o);
const std::vector<sim::Formulation>& formulations_of(const StudyOptions& o);
std::vector<physics::Case> cases_of(const StudyOptions& o);
// The work-precision study's problems: the presets of cases_of, then the custom body.
std::vector<Problem> problems_of(const StudyOptions& o);
Problem preset_problem(physics::Case c);
// A body of one's own from a checked run (a job's simulation), named after
// its case (a preset's name, or "custom"), with the run's final time.
Problem run_problem(const sim::RunSpec& spec);
// The presets of a comma-separated list (`epviz bench --cases`; "" for none).
// "custom" stands for the body of one's own and is left out of the list:
// `have_custom` says whether there is one. Throws io::BadInput naming
// --cases and what is allowed.
std::vector<physics::Case> parse_case_list(const std::string& list, bool have_custom);
// A run of `p` as sim::preset_run makes one of a preset.
sim::RunSpec problem_run(const Problem& p, sim::Method m, sim::Formulation f, double t_end,
                         int samples);
int repeats_of(const StudyOptions& o);
// Tells o.progress (if any) what runs next.
void tell(const StudyOptions& o, const std::string& what);

}  // namespace epviz::study
