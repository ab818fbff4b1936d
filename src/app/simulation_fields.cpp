#include "app/simulation_fields.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <sstream>
#include <variant>

#include "app/cli_values.hpp"
#include "io/bad_input.hpp"
#include "io/printable.hpp"

namespace epviz::app {
void add_simulation_options(CLI::App& cmd, SimulationOptions& o) {
  const auto& table = job::simulation_field_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& f = table[i];
    if (f.type == job::FieldType::flag) {
      cmd.add_flag(f.flag, o.values[i].set, f.help);
      continue;
    }
    std::string help = f.help;
    if (!f.choices.empty()) help += ": " + f.choices;
    if (f.key == "case") help += "; all: every preset";  // simulate runs each in turn
    if (const auto range = f.range_text(); !range.empty()) help += " (" + range + ")";
    if (!f.default_value.empty()) help += " (default " + f.default_value + ")";
    cmd.add_option(f.flag, o.values[i].text, help);
  }
}

namespace {

// The value of one option into its field, converted and checked against the
// field's range as the job's key is.
void set_from_option(const job::FieldInfo& f, const SimulationOptions::Value& v,
                     Given<std::string>& g) {
  if (!v.text.empty()) g.set(v.text, f.flag);
}
// Each of `numbers`, read from `text`, within the field's range.
template <class Numbers>
void require_in_range(const job::FieldInfo& f, const std::string& text, const Numbers& numbers) {
  for (double x : numbers)
    if (!f.in_range(x))
      throw io::BadInput(f.flag + ": expected " + f.range_text() + ", got '" + io::printable(text) +
                         "'");
}
void set_from_option(const job::FieldInfo& f, const SimulationOptions::Value& v,
                     Given<std::array<double, 3>>& g) {
  if (v.text.empty()) return;
  const auto x = parse_vec3(f.flag, v.text);
  require_in_range(f, v.text, x);
  g.set(x, f.flag);
}
void set_from_option(const job::FieldInfo& f, const SimulationOptions::Value& v, Given<double>& g) {
  if (v.text.empty()) return;
  const double x = parse_number(f.flag, v.text);
  require_in_range(f, v.text, std::array<double, 1>{x});
  g.set(x, f.flag);
}
void set_from_option(const job::FieldInfo& f, const SimulationOptions::Value& v, Given<long>& g) {
  if (!v.text.empty()) g.set(parse_integer(f.flag, v.text, long(f.min), long(f.max)), f.flag);
}
void set_from_option(const job::FieldInfo& f, const SimulationOptions::Value& v, Given<bool>& g) {
  if (v.set) g.set(f.flag_sets, f.flag);
}

}  // namespace

SimulationFields fields_from_options(const SimulationOptions& o) {
  SimulationFields fields;
  const auto& table = job::simulation_field_table();
  for (std::size_t i = 0; i < table.size(); ++i)
    std::visit([&](auto m) { set_from_option(table[i], o.values[i], fields.*m); }, table[i].member);
  return fields;
}

}  // namespace epviz::app
