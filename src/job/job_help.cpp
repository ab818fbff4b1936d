#include "job/job_help.hpp"

#include "job/job_file.hpp"

namespace epviz::job {

std::string value_type_name(ValueType type) {
  switch (type) {
    case ValueType::boolean: return "boolean";
    case ValueType::integer: return "integer";
    case ValueType::number: return "number";
    case ValueType::text: return "text";
    case ValueType::choice: return "choice";
    case ValueType::vec3: return "three numbers";
    case ValueType::colour: return "colour";
    case ValueType::object: return "object";
  }
  return "value";
}

std::string key_help(const KeyInfo& key) {
  std::string line = "  " + key.path + " (" + value_type_name(key.type);
  if (!key.default_value.empty()) line += ", default " + key.default_value;
  line += ")";
  if (!key.allowed.empty()) line += ": " + key.allowed;
  line += "\n";
  if (!key.help.empty()) line += "      " + key.help + "\n";
  return line;
}

namespace {

std::string section(const std::string& title, const std::vector<KeyInfo>& keys) {
  std::string text = title + "\n";
  for (const auto& k : keys) text += key_help(k);
  return text;
}

}  // namespace

std::string job_keys_help() {
  return section(
             "A render job (a JSON object; every key may be left out but \"simulation\"; a "
             "simulation key without a default takes the case's value):",
             render_job_keys()) +
         "\n" +
         section("A gallery (a top-level \"jobs\" key): one still of each job, tiled:",
                 gallery_job_keys()) +
         "\n" +
         section("The figures of epviz bench (a top-level \"bench\" key):", bench_job_keys());
}

}  // namespace epviz::job
