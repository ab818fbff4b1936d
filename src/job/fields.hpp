#pragma once
// The fields of a simulation in one table: each with its job key, its
// command-line option, its type and range, its default, its help and
// whether a sweep may vary it. The job reader, the options of `epviz
// simulate`, a sweep's axes and every range check loop over it, so a field
// or a bound is written here once.
#include <array>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "job/document.hpp"

namespace epviz::job {

// Bounds on numbers a job (or `epviz simulate`) may give beyond their type:
// wide enough for any unit system, narrow enough that energies, steps and
// the drawn body's proportions stay finite in double and float arithmetic.
inline constexpr long max_samples = 100'000'000;
inline constexpr double min_moment = 1e-6, max_moment = 1e6;  // each principal moment
inline constexpr double max_magnitude = 1e6;  // each component of com, omega, gamma; weight
inline constexpr double min_tol = 1e-15, max_tol = 0.1;
// The most fixed steps (t_end / step) or FTLE windows (t_end / window) of one run.
inline constexpr double max_steps_per_run = 1e9;

enum class FieldType { text, vec3, number, integer, flag };

template <class T>
using FieldOf = Given<T> SimulationFields::*;
using FieldMember = std::variant<FieldOf<std::string>, FieldOf<std::array<double, 3>>,
                                 FieldOf<double>, FieldOf<long>, FieldOf<bool>>;

struct FieldInfo {
  std::string key;   // "t_end": the job's key and the sweep's axis name
  std::string flag;  // "--t-end"
  FieldType type = FieldType::text;
  FieldMember member;
  // Numbers, integers and each component of a vector: from min to max;
  // min_exclusive: more than min ("> 0").
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  std::string default_value;  // as a job would write it; empty: the case's
  std::string help;
  std::string choices;  // text: the names allowed, "dop853, rk4, ..."
  bool sweepable = true;
  bool flag_sets = true;  // flags: the value the option sets (--no-chart-switch: false)

  bool in_range(double x) const;
  // "a number from 1e-15 to 0.1", "a positive number", "three numbers from
  // -1e6 to 1e6", "an integer from 1 to 100000000"; empty for text and flags.
  std::string range_text() const;
};

// Every field, in the order a job writes them.
const std::vector<FieldInfo>& simulation_field_table();
// The field called `key`; nullptr when there is none.
const FieldInfo* find_field(std::string_view key);

// Calls f(info, given) for each field of `fields` (const or not), `given`
// being its Given<T>.
template <class Fields, class F>
void for_each_field(Fields& fields, F&& f) {
  for (const auto& info : simulation_field_table())
    std::visit([&](auto member) { f(info, fields.*member); }, info.member);
}

// A bound as messages and the keys' table write it: "1e-6", "0.01", "1000".
std::string format_number(double value);

// The case presets' names: "euler, lagrange, ..., generic".
std::string case_names();

}  // namespace epviz::job
