#include "job/field_options.hpp"

#include <array>
#include <variant>

#include "io/bad_input.hpp"
#include "io/option_values.hpp"
#include "io/printable.hpp"

namespace epviz::job {
namespace {

// The value of one option into its field, converted and checked against the
// field's range as the job's key is.
void set_from_option(const FieldInfo& f, const SimulationOptions::Value& v, Given<std::string>& g) {
  if (!v.text.empty()) g.set(v.text, f.flag);
}
// Each of `numbers`, read from `text`, within the field's range.
template <class Numbers>
void require_option_in_range(const FieldInfo& f, const std::string& text, const Numbers& numbers) {
  for (double x : numbers)
    if (!f.in_range(x))
      throw io::BadInput(f.flag + ": expected " + f.range_text() + ", got '" + io::printable(text) +
                         "'");
}
void set_from_option(const FieldInfo& f, const SimulationOptions::Value& v,
                     Given<std::array<double, 3>>& g) {
  if (v.text.empty()) return;
  const auto x = io::parse_vec3(f.flag, v.text);
  require_option_in_range(f, v.text, x);
  g.set(x, f.flag);
}
void set_from_option(const FieldInfo& f, const SimulationOptions::Value& v, Given<double>& g) {
  if (v.text.empty()) return;
  const double x = io::parse_number(f.flag, v.text);
  require_option_in_range(f, v.text, std::array<double, 1>{x});
  g.set(x, f.flag);
}
void set_from_option(const FieldInfo& f, const SimulationOptions::Value& v, Given<long>& g) {
  if (!v.text.empty()) g.set(io::parse_integer(f.flag, v.text, long(f.min), long(f.max)), f.flag);
}
void set_from_option(const FieldInfo& f, const SimulationOptions::Value& v, Given<bool>& g) {
  if (v.set) g.set(f.flag_sets, f.flag);
}

}  // namespace

SimulationFields fields_from_options(const SimulationOptions& o) {
  SimulationFields fields;
  const auto& table = simulation_field_table();
  for (std::size_t i = 0; i < table.size(); ++i)
    std::visit([&](auto m) { set_from_option(table[i], o.values[i], fields.*m); }, table[i].member);
  return fields;
}

}  // namespace epviz::job
