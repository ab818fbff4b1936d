#include "study/options.hpp"

#include <sstream>

#include "io/bad_input.hpp"

namespace epviz::study {

const std::vector<sim::Method>& methods_of(const StudyOptions& o) {
  return o.methods.empty() ? sim::all_methods() : o.methods;
}

const std::vector<sim::Formulation>& formulations_of(const StudyOptions& o) {
  return o.formulations.empty() ? sim::all_formulations() : o.formulations;
}

std::vector<physics::Case> cases_of(const StudyOptions& o) {
  if (!o.cases.empty() || o.custom) return o.cases;
  std::vector<physics::Case> all;
  for (const auto& p : physics::case_presets()) all.push_back(p.id);
  return all;
}

Problem preset_problem(physics::Case c) {
  const auto& p = physics::preset(c);
  return {c, p.name, p.body, p.initial};
}

Problem run_problem(const sim::RunSpec& spec) {
  Problem p;
  p.id = spec.case_id;
  p.name = physics::case_name(spec.case_id);
  p.body = spec.body;
  p.initial = spec.initial;
  p.t_end = spec.t_end;
  return p;
}

std::vector<physics::Case> parse_case_list(const std::string& list, bool have_custom) {
  std::vector<physics::Case> cases;
  if (list.empty()) return cases;
  std::stringstream s(list);
  std::string item;
  while (std::getline(s, item, ',')) {
    const auto c = physics::case_from_name(item);
    if (c == physics::Case::custom) {
      if (!have_custom)
        throw io::BadInput(
            "--cases: 'custom' needs --job FILE (a render job whose \"simulation\" gives the "
            "body)");
      continue;
    }
    if (!c) {
      std::string names;
      for (const auto& p : physics::case_presets()) names += (names.empty() ? "" : ", ") + p.name;
      throw io::BadInput("--cases: unknown case '" + item +
                         "' (expected a comma-separated list of " + names +
                         (have_custom ? ", custom" : "") + ")");
    }
    cases.push_back(*c);
  }
  return cases;
}

std::vector<Problem> problems_of(const StudyOptions& o) {
  std::vector<Problem> all;
  for (const auto c : cases_of(o)) all.push_back(preset_problem(c));
  if (o.custom) all.push_back(*o.custom);
  return all;
}

sim::RunSpec problem_run(const Problem& p, sim::Method m, sim::Formulation f, double t_end,
                         int samples) {
  return sim::body_run(p.id, p.body, p.initial, m, f, t_end, samples);
}

int repeats_of(const StudyOptions& o) { return o.repeats > 0 ? o.repeats : (o.quick ? 3 : 5); }

void tell(const StudyOptions& o, const std::string& what) {
  if (o.progress) o.progress(what);
}

}  // namespace epviz::study
