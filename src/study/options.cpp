#include "study/options.hpp"

namespace epviz::study {

const std::vector<sim::Method>& methods_of(const StudyOptions& o) {
  return o.methods.empty() ? sim::all_methods() : o.methods;
}

const std::vector<sim::Formulation>& formulations_of(const StudyOptions& o) {
  return o.formulations.empty() ? sim::all_formulations() : o.formulations;
}

std::vector<physics::Case> cases_of(const StudyOptions& o) {
  if (!o.cases.empty()) return o.cases;
  std::vector<physics::Case> all;
  for (const auto& p : physics::case_presets()) all.push_back(p.id);
  return all;
}

int repeats_of(const StudyOptions& o) { return o.repeats > 0 ? o.repeats : (o.quick ? 3 : 5); }

void tell(const StudyOptions& o, const std::string& what) {
  if (o.progress) o.progress(what);
}

}  // namespace epviz::study
