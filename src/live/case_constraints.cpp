#include "live/case_constraints.hpp"

namespace epviz::live {
namespace {

// The moment an edit keeps where the case ties the moments: the one edited,
// or the first when the edit was of something else.
physics::Moment kept_moment(Edited edited) {
  switch (edited) {
    case Edited::inertia_2: return physics::Moment::second;
    case Edited::inertia_3: return physics::Moment::third;
    case Edited::inertia_1:
    case Edited::com:
    case Edited::weight:
    case Edited::omega:
    case Edited::gamma: break;
  }
  return physics::Moment::first;
}

}  // namespace

void enforce_case(physics::Case c, Edited edited, physics::Body& body, physics::InitialState& s) {
  physics::fit_to_case(c, kept_moment(edited), body, s);
}

const char* case_conditions_summary(physics::Case c) {
  if (c == physics::Case::custom) return "none";
  return physics::preset(c).panel_conditions.c_str();
}

}  // namespace epviz::live
