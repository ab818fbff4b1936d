// job::fields_from_options: the text of `epviz simulate`'s options becomes
// the simulation fields, each named by its option, and a value that is not of
// the field's type or lies outside its range is refused naming the option.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <string>

#include "io/bad_input.hpp"
#include "job/field_options.hpp"

namespace epviz::job {
namespace {

// Options with the texts given by flag ("--inertia" -> "1,1,0.5"); a flag
// mapped to "" is a flag that is set.
SimulationOptions options(const std::map<std::string, std::string>& given) {
  SimulationOptions o;
  const auto& table = simulation_field_table();
  for (const auto& [flag, text] : given) {
    std::size_t i = 0;
    while (i < table.size() && table[i].flag != flag) ++i;
    if (i == table.size()) {
      ADD_FAILURE() << "no field has the option " << flag;
      continue;
    }
    o.values[i].text = text;
    o.values[i].set = text.empty();
  }
  return o;
}

std::string error_of(const std::map<std::string, std::string>& given) {
  try {
    (void)fields_from_options(options(given));
  } catch (const io::BadInput& e) {
    return e.what();
  }
  return "";
}

TEST(FieldOptions, ValuesBecomeFieldsNamedByTheirOption) {
  const auto f = fields_from_options(options({{"--inertia", "1,1,0.5"},
                                              {"--t-end", "40"},
                                              {"--samples", "20"},
                                              {"--method", "rk4"},
                                              {"--no-chart-switch", ""},
                                              {"--normalize-gamma", ""}}));
  ASSERT_TRUE(f.inertia);
  EXPECT_EQ(*f.inertia, (std::array<double, 3>{1.0, 1.0, 0.5}));
  EXPECT_EQ(f.inertia.origin, "--inertia");
  ASSERT_TRUE(f.t_end);
  EXPECT_EQ(*f.t_end, 40.0);
  EXPECT_EQ(f.t_end.origin, "--t-end");
  ASSERT_TRUE(f.samples);
  EXPECT_EQ(*f.samples, 20);
  ASSERT_TRUE(f.method);
  EXPECT_EQ(*f.method, "rk4");
  // --no-chart-switch turns the switch off; --normalize-gamma turns its field on.
  ASSERT_TRUE(f.chart_switch);
  EXPECT_FALSE(*f.chart_switch);
  EXPECT_EQ(f.chart_switch.origin, "--no-chart-switch");
  ASSERT_TRUE(f.normalize_gamma);
  EXPECT_TRUE(*f.normalize_gamma);
  // What was not given stays not given, for the job file or the case to give.
  EXPECT_FALSE(f.case_name);
  EXPECT_FALSE(f.com);
  EXPECT_FALSE(f.tol);
  EXPECT_FALSE(f.allow_nonphysical);
}

TEST(FieldOptions, NoOptionsGiveNoFields) {
  const auto f = fields_from_options(SimulationOptions{});
  EXPECT_FALSE(f.case_name || f.inertia || f.com || f.omega || f.gamma || f.weight || f.tol ||
               f.step || f.t_end || f.max_drift || f.samples || f.formulation || f.method ||
               f.allow_nonphysical || f.normalize_gamma || f.chart_switch);
}

TEST(FieldOptions, AValueOutsideItsRangeIsRefusedNamingTheOption) {
  EXPECT_EQ(error_of({{"--tol", "0.5"}}), "--tol: expected a number from 1e-15 to 0.1, got '0.5'");
  // One component out of range is enough.
  const auto inertia = error_of({{"--inertia", "1,1,2e6"}});
  EXPECT_EQ(inertia.rfind("--inertia: ", 0), 0u) << inertia;
  EXPECT_NE(inertia.find("'1,1,2e6'"), std::string::npos) << inertia;
  const auto samples = error_of({{"--samples", "0"}});
  EXPECT_EQ(samples.rfind("--samples", 0), 0u) << samples;
  const auto step = error_of({{"--step", "-1"}});
  EXPECT_EQ(step.rfind("--step: ", 0), 0u) << step;
}

TEST(FieldOptions, AValueOfTheWrongTypeIsRefusedNamingTheOption) {
  for (const auto& [flag, text] : std::map<std::string, std::string>{
           {"--weight", "heavy"}, {"--com", "0,0"}, {"--samples", "2.5"}, {"--t-end", "1e999"}}) {
    const auto e = error_of({{flag, text}});
    EXPECT_EQ(e.rfind(flag, 0), 0u) << flag << " " << text << ": '" << e << "'";
  }
}

}  // namespace
}  // namespace epviz::job
