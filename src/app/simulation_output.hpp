#pragma once
// Turning a run into the files users read: the CSV of samples and the JSON report.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "sim/drift.hpp"
#include "sim/run_spec.hpp"
#include "sim/simulate.hpp"

namespace epviz::app {

// Header: t,omega1,omega2,omega3,gamma1,gamma2,gamma3,a,b,energy,area,gamma_norm_error,extra_integral
// a, b are the stereographic coordinates of gamma (empty at gamma3 = -1);
// gamma_norm_error is |gamma| - 1; extra_integral is empty without a fourth integral.
std::string samples_csv(const sim::RunSpec& spec, const sim::RunResult& result);

nlohmann::json run_report(const sim::RunSpec& spec, const sim::RunResult& result,
                          const sim::Drifts& drift);

}  // namespace epviz::app
