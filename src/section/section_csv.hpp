#pragma once
// The crossings of a section as CSV, one row per crossing, orbits in order:
//   orbit,crossing,t,omega1,omega2,omega3,gamma1,gamma2,gamma3,energy,area,gamma_norm_error,extra_integral
// energy is C1, area C0, gamma_norm_error |gamma| - 1, extra_integral the
// case's fourth integral (empty without one). Numbers are the shortest text
// that reads back as the same double.
#include <string>
#include <vector>

#include "section/section_job.hpp"
#include "section/section_run.hpp"

namespace epviz::section {

// Orbits with a failure are left out: a lost orbit is no result.
std::string crossings_csv(const SectionJob& job, const std::vector<OrbitResult>& orbits);

// Writes crossings_csv to job.csv under a temporary name, then renames it.
void write_crossings_csv(const SectionJob& job, const std::vector<OrbitResult>& orbits);

}  // namespace epviz::section
