// The line a user reads on a numerical failure, for failures that really
// happen: every kind is provoked (Euler-Poisson runs where the kind arises in
// them, the small test systems of the numerics tests otherwise), and its line
// must be one complete sentence: the fact from numerics, whole and naming no
// option, then the front end's advice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "numerics/embedded_rk.hpp"
#include "numerics/provoked_failures.hpp"
#include "sim/failure_advice.hpp"
#include "sim/simulate.hpp"

namespace epviz {
namespace {

using numerics::Failure;
using numerics::FailureKind;

sim::RunSpec fast_top(sim::Method m, double step, double t_end, int samples) {
  auto spec = sim::preset_run(physics::Case::lagrange, m, sim::Formulation::direct, t_end, samples);
  const double tilt = 5.0 * std::numbers::pi / 180.0;
  spec.initial.omega = {0.0, 0.0, 50.0};
  spec.initial.gamma = {std::sin(tilt), 0.0, std::cos(tilt)};
  spec.step = step;
  return spec;
}

Failure failed_run(const sim::RunSpec& spec) {
  const auto r = sim::simulate(spec);
  EXPECT_TRUE(r.failure.has_value()) << sim::name(spec.method);
  return r.failure.value_or(Failure{});
}

std::vector<Failure> real_failures() {
  using namespace numerics;
  using namespace numerics::testing;
  std::vector<Failure> all;
  // lost_motion: RK4 beyond its stability limit, still finite at the first output time.
  all.push_back(failed_run(fast_top(sim::Method::rk4, 2.0, 40.0, 20)));
  // non_finite: the same, with one output time only, overflows between output times.
  all.push_back(failed_run(fast_top(sim::Method::rk4, 2.0, 4000.0, 1)));
  // solver_divergence: the implicit stages cannot converge with a step longer than a period.
  all.push_back(failed_run(fast_top(sim::Method::gauss4, 5.0, 20.0, 2)));
  {  // chart_pole: the north Riccati chart through the south pole.
    auto spec = sim::preset_run(physics::Case::euler, sim::Method::dop853,
                                sim::Formulation::riccati, 6.0, 60);
    spec.initial.omega = {1.0, 0.0, 0.0};
    spec.initial.gamma = {0.0, 0.6, 0.8};
    spec.chart_switch = false;
    all.push_back(failed_run(spec));
  }
  // step_underflow, step_budget, rejections: from the step control on tiny test systems.
  for (const Failure& f : numerics::testing::step_control_failures()) all.push_back(f);
  return all;
}

// Words a sentence cannot end on.
bool ends_in_fragment(const std::string& text) {
  static const std::set<std::string> dangling = {
      "a",     "an", "the",  "and",  "or",   "but",  "of",    "to",    "in",   "on",
      "at",    "by", "for",  "from", "with", "into", "where", "which", "that", "when",
      "finds", "if", "than", "as",   "is",   "are",  "be",    "while", "so",   "its"};
  std::size_t end = text.size();
  while (end > 0 && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  if (end == 0) return true;
  if (std::string(",:;(-").find(text[end - 1]) != std::string::npos) return true;
  std::size_t begin = end;
  while (begin > 0 && std::isalpha(static_cast<unsigned char>(text[begin - 1]))) --begin;
  std::string last = text.substr(begin, end - begin);
  std::transform(last.begin(), last.end(), last.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return dangling.count(last) > 0;
}

bool balanced(const std::string& s) {
  int depth = 0;
  for (char c : s) {
    depth += c == '(' ? 1 : c == ')' ? -1 : 0;
    if (depth < 0) return false;
  }
  return depth == 0;
}

TEST(FailureLine, EveryKindReadsAsOneCompleteSentence) {
  std::set<FailureKind> seen;
  for (const Failure& f : real_failures()) {
    seen.insert(f.kind);
    // The fact from numerics: whole, and naming no command-line option.
    SCOPED_TRACE(std::string(numerics::name(f.kind)) + ": " + f.message());
    EXPECT_FALSE(f.detail.empty());
    EXPECT_FALSE(ends_in_fragment(f.detail)) << f.detail;
    EXPECT_TRUE(balanced(f.detail)) << f.detail;
    EXPECT_EQ(f.message().find("--"), std::string::npos);
    EXPECT_EQ(f.message().find(';'), std::string::npos) << "advice belongs to the front end";
    for (auto where :
         {sim::SettingsIn::command_line, sim::SettingsIn::render_job, sim::SettingsIn::panel}) {
      const std::string line = sim::failure_line(f, where);
      EXPECT_EQ(line.rfind(f.method + " failed at t = ", 0), 0u) << line;
      EXPECT_EQ(line.find('\n'), std::string::npos) << line;
      ASSERT_EQ(line.back(), '.') << line;
      EXPECT_EQ(line.find(".."), std::string::npos) << line;
      EXPECT_FALSE(ends_in_fragment(line.substr(0, line.size() - 1))) << line;
      EXPECT_TRUE(balanced(line)) << line;
      // Exactly the fact, then the advice.
      EXPECT_EQ(line.rfind(f.message() + "; ", 0), 0u) << line;
      EXPECT_GT(line.size(), f.message().size() + 12) << line;
    }
  }
  for (FailureKind k : numerics::kFailureKinds)
    EXPECT_TRUE(seen.count(k)) << numerics::name(k) << " was not provoked";
}

TEST(FailureLine, FragmentCheckCatchesWhatItLooksFor) {
  // The check above must be able to fail.
  EXPECT_TRUE(ends_in_fragment("an adaptive method (dop853) finds where"));
  EXPECT_TRUE(ends_in_fragment("step size 3e-17 below the"));
  EXPECT_TRUE(ends_in_fragment("state not finite,"));
  EXPECT_FALSE(ends_in_fragment("step size 3e-17 below the round-off limit"));
  EXPECT_FALSE(balanced("trial states not finite (NaN or Inf"));
}

}  // namespace
}  // namespace epviz
