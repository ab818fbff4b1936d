// The interactive view's advice on a numerical failure: for every kind, a
// complete sentence naming a control of the panel, never a command-line option.
#include "live/failure_advice.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <string>

namespace epviz::live {
namespace {

using numerics::FailureKind;

TEST(LiveFailureAdvice, EveryKindNamesAPanelControl) {
  // The Integrator panel's controls and the Case and body panel.
  const char* const controls[] = {"tolerance",   "step",         "method",
                                  "formulation", "chart switch", "Case and body"};
  for (FailureKind k : numerics::kFailureKinds) {
    for (bool adaptive : {true, false}) {
      const std::string a = failure_advice(k, adaptive);
      SCOPED_TRACE(std::string(numerics::name(k)) + (adaptive ? " adaptive: " : " fixed: ") + a);
      ASSERT_GT(a.size(), 10u);
      EXPECT_TRUE(std::islower(static_cast<unsigned char>(a.front())));
      EXPECT_EQ(a.back(), '.');
      EXPECT_EQ(a.find(". "), std::string::npos);
      EXPECT_EQ(a.find("--"), std::string::npos);
      EXPECT_NE(a.find(" panel"), std::string::npos);
      bool names_control = false;
      for (const char* c : controls) names_control |= a.find(c) != std::string::npos;
      EXPECT_TRUE(names_control);
      // A fixed-step method has no tolerance control, an adaptive one no step control.
      if (k != FailureKind::chart_pole) {
        EXPECT_EQ(a.find(adaptive ? "the step" : "the tolerance"), std::string::npos);
      }
    }
  }
}

TEST(LiveFailureAdvice, LineIsMessageThenAdvice) {
  const numerics::Failure f{3.25, "rk4", FailureKind::non_finite, "state not finite (NaN or Inf)"};
  EXPECT_EQ(failure_line(f, false), "rk4 failed at t = 3.25: state not finite (NaN or Inf); " +
                                        failure_advice(FailureKind::non_finite, false));
  EXPECT_NE(failure_advice(FailureKind::chart_pole, true).find("spinor"), std::string::npos);
}

}  // namespace
}  // namespace epviz::live
