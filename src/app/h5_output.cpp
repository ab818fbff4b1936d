#include "app/h5_output.hpp"

#include <string>

#include "job/fields.hpp"
#include "numerics/simd_path.hpp"

namespace epviz::app {

void write_provenance(h5::ColumnsFile& file) {
  file.set_attribute("epviz_version", std::string(EPVIZ_VERSION));
  file.set_attribute("simd_path", std::string(numerics::name(numerics::chosen_simd_path())));
}

nlohmann::json given_fields_json(const job::SimulationFields& fields) {
  nlohmann::json j = nlohmann::json::object();
  job::for_each_field(fields, [&](const job::FieldInfo& info, const auto& given) {
    if (given) j[info.key] = *given;
  });
  return j;
}

}  // namespace epviz::app
