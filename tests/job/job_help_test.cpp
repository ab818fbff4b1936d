// `epviz render --help-job`: every key of the job formats with its type,
// default and allowed values, from the tables that read the jobs.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/json_reader.hpp"
#include "job/fields.hpp"
#include "job/job_help.hpp"

namespace epviz::job {
namespace {

namespace fs = std::filesystem;

// The line of `key` in the help, or empty when it has none.
std::string line_of(const std::string& help, const std::string& key) {
  const auto at = help.find("\n  " + key + " (");
  if (at == std::string::npos) return "";
  return help.substr(at + 1, help.find('\n', at + 1) - at - 1);
}

// "a.b" for every key of every object in `j` (arrays not entered: a run's keys
// are the simulation's).
void key_paths(const nlohmann::json& j, const std::string& prefix, std::vector<std::string>& out) {
  for (const auto& [key, value] : j.items()) {
    out.push_back(prefix + key);
    if (value.is_object()) key_paths(value, prefix + key + ".", out);
  }
}

TEST(JobHelp, ExplainsEveryKeyTheShippedJobsUse) {
  const auto help = job_keys_help();
  int keys = 0;
  for (const auto& e : fs::directory_iterator(fs::path(EPVIZ_SOURCE_DIR) / "render_jobs")) {
    const auto name = e.path().filename().string();
    if (e.path().extension() != ".json" || name.find(".sweep.") != std::string::npos ||
        name.find(".section.") != std::string::npos)
      continue;  // other commands' files
    std::vector<std::string> paths;
    key_paths(io::read_json_file(e.path()), "", paths);
    for (const auto& p : paths) {
      EXPECT_FALSE(line_of(help, p).empty()) << name << ": " << p;
      ++keys;
    }
  }
  EXPECT_GT(keys, 20);
}

TEST(JobHelp, EachSimulationKeyShowsTheFieldTablesTypeDefaultAndRange) {
  const auto help = job_keys_help();
  for (const auto& f : simulation_field_table()) {
    const auto line = line_of(help, "simulation." + f.key);
    ASSERT_FALSE(line.empty()) << f.key;
    if (!f.range_text().empty()) {
      EXPECT_NE(line.find(f.range_text()), std::string::npos) << line;
    }
    if (!f.choices.empty()) {
      EXPECT_NE(line.find(f.choices), std::string::npos) << line;
    }
    // A render job's tolerance follows its resolution unless given.
    const auto dflt = f.key == "tol" ? std::string("auto") : f.default_value;
    if (!dflt.empty()) {
      EXPECT_NE(line.find(", default " + dflt + ")"), std::string::npos) << line;
    }
    EXPECT_NE(help.find(line + "\n      " + f.help + "\n"), std::string::npos) << f.key;
  }
}

TEST(JobHelp, AKeyIsItsPathTypeDefaultAllowedValuesThenItsHelp) {
  EXPECT_EQ(
      key_help({"camera.distance", ValueType::number, "3", "more than 1.2", "from the centre"}),
      "  camera.distance (number, default 3): more than 1.2\n      from the centre\n");
  EXPECT_EQ(key_help({"camera", ValueType::object, "", "", ""}), "  camera (object)\n");
  EXPECT_EQ(value_type_name(ValueType::vec3), "three numbers");
}

}  // namespace
}  // namespace epviz::job
