#include "app/simulation_fields.hpp"

namespace epviz::app {
void add_simulation_options(cli::Command cmd, SimulationOptions& o) {
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

}  // namespace epviz::app
