#pragma once
// What a bench run asks of the studies, and the defaults they fill in.
#include <functional>
#include <string>
#include <vector>

#include "physics/cases.hpp"
#include "sim/run_spec.hpp"

namespace epviz::study {

struct StudyOptions {
  bool quick = false;
  std::vector<physics::Case> cases;            // work-precision cases; empty = all six presets
  std::vector<sim::Method> methods;            // empty = sim::all_methods()
  std::vector<sim::Formulation> formulations;  // empty = sim::all_formulations()
  int repeats = 0;                             // CPU-time repeats; 0 = 3 (quick) or 5 (full)
  std::function<void(const std::string&)> progress;  // optional: told what runs next
};

const std::vector<sim::Method>& methods_of(const StudyOptions& o);
const std::vector<sim::Formulation>& formulations_of(const StudyOptions& o);
std::vector<physics::Case> cases_of(const StudyOptions& o);
int repeats_of(const StudyOptions& o);
// Tells o.progress (if any) what runs next.
void tell(const StudyOptions& o, const std::string& what);

}  // namespace epviz::study
