#pragma once
// The crossings of a section as CSV, one row per crossing, runs in order
// (section_run_of: method by method, orbits in order within each):
//   orbit,crossing,t,omega1,omega2,omega3,gamma1,gamma2,gamma3,energy,area,gamma_norm_error,extra_integral
// with a first column `method` ("rk4 step 0.05", method_label) when the
// section lists several methods. energy is C1, area C0, gamma_norm_error
// |gamma| - 1, extra_integral the case's fourth integral (empty without
// one), and after it a column for each plotted Andoyer–Deprit variable
// (andoyer_l, ..., empty where it is undefined). Numbers are the shortest text that reads back as the same double,
// so that the CSV read back (crossings_from_csv) gives the same crossings.
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "section/section_job.hpp"
#include "section/section_run.hpp"

namespace epviz::section {

// The header line, with its newline.
std::string crossings_csv_header(const SectionJob& job);

// The header and a row per crossing. Orbits with a failure are left out: a
// lost orbit is no result.
std::string crossings_csv(const SectionJob& job, const std::vector<OrbitResult>& orbits);

// The same crossings as numbers (an HDF5 file's datasets, Python's arrays):
// the CSV's column names, and each row's values in that order. The method
// column (several methods only) holds the method's index into job.methods
// (0, 1, ...); extra_integral and the Andoyer–Deprit columns are NaN where
// the CSV's field is empty. Orbits
// with a failure are left out, as from the CSV.
std::vector<std::string> crossing_columns(const SectionJob& job);
void for_each_crossing_row(const SectionJob& job, const std::vector<OrbitResult>& orbits,
                           const std::function<void(std::span<const double>)>& row);

// Writes crossings_csv to job.csv under a temporary name, then renames it.
void write_crossings_csv(const SectionJob& job, const std::vector<OrbitResult>& orbits);

// The rows of a crossings CSV (after its header, which must be job's) as
// results, one per run that has a crossing, in the order of the rows; `file`
// names it in messages. Throws io::BadInput naming the file and line for a
// row that is not one crossing of job's methods, or out of order.
std::vector<OrbitResult> crossings_from_csv(const SectionJob& job, std::string_view text,
                                            const std::string& file);

}  // namespace epviz::section
