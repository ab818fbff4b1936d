// The plain-text tables `epviz bench` prints: columns padded to their widest
// cell, a table per case for the work-precision runs, nothing for a study
// without rows.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "study/bench_tables.hpp"
#include "study/text_table.hpp"

namespace epviz {
namespace {

TEST(TextTable, ColumnsAsWideAsTheirWidestCell) {
  EXPECT_EQ(study::text_table("t", {"a", "bbb"}, {{"xx", "y"}, {"z", "w"}}),
            "\nt\n"
            "a  bbb \n"
            "xx y   \n"
            "z  w   \n");
  EXPECT_EQ(study::text_table("t", {"a"}, {}), "");
}

TEST(TextTable, NumbersToThreeDigits) {
  EXPECT_EQ(study::cell_number(3.14159), "3.14");
  EXPECT_EQ(study::cell_number(12345.0), "1.23e+04");
  EXPECT_EQ(study::cell_number(NAN), "-");
  EXPECT_EQ(study::cell_number(INFINITY), "-");
}

// Lines of `text` that start with `prefix`.
int lines_starting(const std::string& text, const std::string& prefix) {
  int n = 0;
  for (std::size_t at = 0; at < text.size();) {
    const auto end = text.find('\n', at);
    if (text.compare(at, prefix.size(), prefix) == 0) ++n;
    at = end == std::string::npos ? text.size() : end + 1;
  }
  return n;
}

study::WorkPrecisionRow run_of(const std::string& case_name, const std::string& method) {
  study::WorkPrecisionRow r;
  r.run.case_name = case_name;
  r.run.method = method;
  r.run.tol = 1e-6;
  r.error = 2e-7;
  return r;
}

TEST(BenchTables, OneWorkPrecisionTablePerReferencedCase) {
  study::ReferenceRow euler, lagrange;
  euler.case_name = "euler";
  lagrange.case_name = "lagrange";
  const auto text =
      study::bench_tables({euler, lagrange, run_of("euler", "dop853"), run_of("lagrange", "rk4"),
                           run_of("euler", "rk4"), run_of("hess", "rk4")});
  EXPECT_EQ(lines_starting(text, "work-precision: euler "), 1) << text;
  EXPECT_EQ(lines_starting(text, "work-precision: lagrange "), 1) << text;
  EXPECT_EQ(lines_starting(text, "impl "), 2) << text;   // one header per table
  EXPECT_EQ(lines_starting(text, "epviz "), 3) << text;  // hess has no reference: not shown
  EXPECT_EQ(text.find("stability"), std::string::npos) << text;
}

TEST(BenchTables, EveryStudyWithRowsHasItsTable) {
  EXPECT_EQ(study::bench_tables({}), "");
  study::MaxStepRow max_step;
  max_step.case_name = "euler";
  max_step.method = "rk4";
  max_step.max_step = 0.25;
  study::ChaosRow chaos;
  chaos.run.method = "dop853";
  const auto text = study::bench_tables({max_step, chaos});
  EXPECT_EQ(lines_starting(text, "stability 1: "), 1) << text;
  EXPECT_EQ(lines_starting(text, "euler "), 1) << text;
  EXPECT_NE(text.find("0.25"), std::string::npos) << text;
  EXPECT_EQ(lines_starting(text, "stability 5: "), 1) << text;
  EXPECT_EQ(lines_starting(text, "stability 2: "), 0) << text;
  EXPECT_LT(text.find("stability 1: "), text.find("stability 5: "));
}

}  // namespace
}  // namespace epviz
