// The command line's advice on a numerical failure (sim/failure_advice): for
// every kind, a complete sentence that names an option `epviz simulate` really
// has, and only one the method accepts (adaptive methods reject --step,
// fixed-step ones --tol).
#include "sim/failure_advice.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "support/cli.hpp"

namespace epviz {
namespace {

using numerics::FailureKind;
using sim::SettingsIn;

// The advice for the command line unless told otherwise.
std::string advice(FailureKind kind, std::string_view method, bool adaptive,
                   SettingsIn where = SettingsIn::command_line) {
  return sim::failure_advice(kind, method, adaptive, where);
}

// The "--word" tokens of a text.
std::vector<std::string> flags_in(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t at = text.find("--"); at != std::string::npos; at = text.find("--", at + 2)) {
    std::size_t end = at + 2;
    while (end < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '-'))
      ++end;
    out.push_back(text.substr(at, end - at));
  }
  return out;
}

void expect_sentence(const std::string& s) {
  ASSERT_GT(s.size(), 10u) << s;
  EXPECT_TRUE(std::islower(static_cast<unsigned char>(s.front())))
      << "continues the line after '; ': " << s;
  EXPECT_EQ(s.back(), '.') << s;
  EXPECT_EQ(s.find(".."), std::string::npos) << s;
  EXPECT_EQ(s.find("  "), std::string::npos) << s;
  // One sentence: no full stop before the end.
  EXPECT_EQ(s.find(". "), std::string::npos) << s;
}

struct Method {
  const char* name;
  bool adaptive;
};
constexpr Method kMethods[] = {
    {"dop853", true}, {"dopri5", true}, {"rk4", false}, {"gauss4", false}};

TEST(FailureAdvice, EveryKindNamesAnOptionOfSimulate) {
  test::TempDir dir;
  const auto help = test::run_epviz("simulate --help", dir);
  ASSERT_EQ(help.exit_code, 0) << help.err;
  for (FailureKind k : numerics::kFailureKinds) {
    for (const Method& m : kMethods) {
      const std::string a = advice(k, m.name, m.adaptive);
      SCOPED_TRACE(std::string(numerics::name(k)) + " " + m.name + ": " + a);
      expect_sentence(a);
      const auto flags = flags_in(a);
      ASSERT_FALSE(flags.empty());
      for (const auto& f : flags) {
        EXPECT_NE(help.out.find(f), std::string::npos)
            << f << " is not an option of epviz simulate";
        // What `epviz simulate` would refuse for this method (bad_input_test).
        if (k != FailureKind::chart_pole) {
          EXPECT_NE(f, m.adaptive ? "--step" : "--tol");
        }
      }
    }
  }
}

TEST(FailureAdvice, KindsGetTheirOwnRemedy) {
  EXPECT_NE(advice(FailureKind::step_underflow, "dop853", true).find("loosen --tol"),
            std::string::npos);
  EXPECT_NE(advice(FailureKind::solver_divergence, "gauss4", false).find("smaller --step"),
            std::string::npos);
  const auto pole = advice(FailureKind::chart_pole, "dop853", true);
  EXPECT_NE(pole.find("--formulation spinor"), std::string::npos) << pole;
  EXPECT_NE(pole.find("--no-chart-switch"), std::string::npos) << pole;
  // A method that needs many steps at tight tolerances is pointed to dop853, dop853 is not.
  EXPECT_NE(advice(FailureKind::step_budget, "dopri5", true).find("--method dop853"),
            std::string::npos);
  EXPECT_EQ(advice(FailureKind::step_budget, "dop853", true).find("--method"), std::string::npos);
}

TEST(FailureAdvice, RenderJobsNameJobKeysNotOptions) {
  for (FailureKind k : numerics::kFailureKinds) {
    for (const Method& m : kMethods) {
      const std::string a = advice(k, m.name, m.adaptive, SettingsIn::render_job);
      SCOPED_TRACE(a);
      expect_sentence(a);
      EXPECT_TRUE(flags_in(a).empty());
      EXPECT_NE(a.find("simulation."), std::string::npos);
    }
  }
}

TEST(FailureAdvice, LineIsMessageThenAdvice) {
  const numerics::Failure f{2.5, "gauss4", FailureKind::solver_divergence,
                            "stage equations diverged"};
  const std::string line = sim::failure_line(f, SettingsIn::command_line);
  EXPECT_EQ(line, "gauss4 failed at t = 2.5: stage equations diverged; " +
                      advice(FailureKind::solver_divergence, "gauss4", false));
  // The method's step control comes from the method table: dop853 is adaptive.
  const numerics::Failure g{1.0, "dop853", FailureKind::non_finite, "state not finite"};
  EXPECT_EQ(sim::failure_line(g, SettingsIn::command_line),
            g.message() + "; " + advice(g.kind, "dop853", true));
}

}  // namespace
}  // namespace epviz
