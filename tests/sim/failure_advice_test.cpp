// The advice on a numerical failure, in each front end's words: for every kind
// and every place, one complete sentence naming a setting that place has. The
// command line's options are checked against `epviz simulate --help` in
// tests/app/failure_advice_test.cpp.
#include "sim/failure_advice.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <string>

#include "sim/run_spec.hpp"

namespace epviz::sim {
namespace {

using numerics::FailureKind;

constexpr SettingsIn kPlaces[] = {SettingsIn::command_line, SettingsIn::render_job,
                                  SettingsIn::panel, SettingsIn::python};

TEST(FailureAdvice, EveryKindIsOneSentenceInEveryPlace) {
  for (SettingsIn where : kPlaces) {
    for (FailureKind k : numerics::kFailureKinds) {
      for (Method m : all_methods()) {
        const std::string a = failure_advice(k, name(m), is_adaptive(m), where);
        SCOPED_TRACE(std::string(numerics::name(k)) + " " + std::string(name(m)) + ": " + a);
        ASSERT_GT(a.size(), 10u);
        EXPECT_TRUE(std::islower(static_cast<unsigned char>(a.front())));
        EXPECT_EQ(a.back(), '.');
        EXPECT_EQ(a.find(".."), std::string::npos);
        EXPECT_EQ(a.find("  "), std::string::npos);
        EXPECT_EQ(a.find(". "), std::string::npos);
        EXPECT_EQ(a.find(" ,"), std::string::npos);
        // Each place names only its own settings.
        EXPECT_EQ(a.find("--") != std::string::npos, where == SettingsIn::command_line);
        EXPECT_EQ(a.find("simulation.") != std::string::npos, where == SettingsIn::render_job);
        EXPECT_EQ(a.find(" panel") != std::string::npos, where == SettingsIn::panel);
        if (where != SettingsIn::python) {
          EXPECT_EQ(a.find("=\""), std::string::npos);
        }
        if (where == SettingsIn::python && k == FailureKind::chart_pole) {
          EXPECT_NE(a.find("formulation=\"spinor\""), std::string::npos);
        }
      }
    }
  }
}

TEST(FailureAdvice, ThePanelNamesItsOwnControls) {
  // The Integrator panel's controls and the Case and body panel; the panel has
  // no end time and no drift limit.
  const char* const controls[] = {"tolerance",   "step",         "method",
                                  "formulation", "chart switch", "Case and body"};
  for (FailureKind k : numerics::kFailureKinds) {
    for (bool adaptive : {true, false}) {
      const std::string a = failure_advice(k, "rk4", adaptive, SettingsIn::panel);
      SCOPED_TRACE(std::string(numerics::name(k)) + (adaptive ? " adaptive: " : " fixed: ") + a);
      bool names_control = false;
      for (const char* c : controls) names_control |= a.find(c) != std::string::npos;
      EXPECT_TRUE(names_control);
      EXPECT_EQ(a.find("end time"), std::string::npos);
      EXPECT_EQ(a.find("drift"), std::string::npos);
      // A fixed-step method has no tolerance control, an adaptive one no step control.
      if (k != FailureKind::chart_pole) {
        EXPECT_EQ(a.find(adaptive ? "step in the" : "tolerance"), std::string::npos);
      }
    }
  }
}

TEST(FailureAdvice, OnlyTheCommandLineAndJobsOfferTheEndTimeAndDriftLimit) {
  for (SettingsIn where : {SettingsIn::command_line, SettingsIn::render_job}) {
    const std::string budget = failure_advice(FailureKind::step_budget, "rk4", false, where);
    EXPECT_TRUE(budget.find("t-end") != std::string::npos ||
                budget.find("t_end") != std::string::npos)
        << budget;
    const std::string lost = failure_advice(FailureKind::lost_motion, "dop853", true, where);
    EXPECT_TRUE(lost.find("max-drift") != std::string::npos ||
                lost.find("max_drift") != std::string::npos)
        << lost;
  }
}

TEST(FailureAdvice, LineIsMessageThenAdvice) {
  const numerics::Failure f{3.25, "rk4", FailureKind::non_finite, "state not finite (NaN or Inf)"};
  EXPECT_EQ(failure_line(f, SettingsIn::panel),
            "rk4 failed at t = 3.25: state not finite (NaN or Inf); " +
                failure_advice(FailureKind::non_finite, "rk4", false, SettingsIn::panel));
  // The method's step control comes from the method table: dop853 is adaptive.
  const numerics::Failure g{1.0, "dop853", FailureKind::non_finite, "state not finite"};
  EXPECT_EQ(failure_line(g, SettingsIn::panel),
            g.message() + "; " + failure_advice(g.kind, "dop853", true, SettingsIn::panel));
  EXPECT_NE(failure_line(g, SettingsIn::panel).find("tolerance"), std::string::npos);
  EXPECT_NE(
      failure_advice(FailureKind::chart_pole, "dop853", true, SettingsIn::panel).find("spinor"),
      std::string::npos);
}

}  // namespace
}  // namespace epviz::sim
