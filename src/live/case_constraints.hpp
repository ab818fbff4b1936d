#pragma once
// Keeping a case's defining conditions while the user edits a body (the
// "stay in case" switch of the interactive panels): after an edit, the
// quantities the conditions tie to the edited one are recomputed from it, so
// the edited value is kept and the others follow. The case table says how
// (physics::fit_to_case); physics::broken_condition() is the oracle that the
// result satisfies the case.
#include "physics/body.hpp"
#include "physics/cases.hpp"

namespace epviz::live {

// Which value the user just changed.
enum class Edited { inertia_1, inertia_2, inertia_3, com, weight, omega, gamma };

// Makes (body, initial) satisfy case `c`'s conditions, keeping the edited
// value where the conditions allow it. Custom and generic bodies are returned
// unchanged. For Hess the moments must already be ordered I1 > I2 > I3 (the
// panel reports the break otherwise: no ordering is invented).
void enforce_case(physics::Case c, Edited edited, physics::Body& body,
                  physics::InitialState& initial);

// The case's conditions in one line for the panel ("I1 = I2 = 2 I3, centre of
// mass on axis 1").
const char* case_conditions_summary(physics::Case c);

}  // namespace epviz::live
