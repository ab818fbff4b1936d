// All of `epviz bench`'s studies in one call: each stage is announced, in
// order, and each study gives rows.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "study/bench_studies.hpp"
#include "study/quick_options.hpp"

namespace epviz {
namespace {

TEST(BenchStudies, EveryStageAnnouncedAndEveryStudyHasRows) {
  // The drift study takes kovalevskaya and goryachev_chaplygin only.
  const auto o = testing::quick_options({sim::Method::dop853, sim::Method::rk4},
                                        {physics::Case::kovalevskaya}, {sim::Formulation::direct});
  std::vector<std::string> stages;
  std::set<std::string> studies;
  const auto rows = study::bench_studies(o, [&](const std::string& line) {
    if (line.ends_with("...")) stages.push_back(line);
  });
  for (const auto& row : rows)
    std::visit([&](const auto& r) { studies.insert(std::string(r.study)); }, row);
  EXPECT_EQ(stages, (std::vector<std::string>{
                        "work-precision...", "peers (Boost.Odeint, GSL, SciPy where available)...",
                        "invariant drift...", "invariant cost...", "stability..."}));
  for (const char* s :
       {"reference", "work_precision", "drift", "invariant_cost", "stability_max_step",
        "stability_pole", "stability_separatrix", "stability_sleeping_top", "stability_chaos"})
    EXPECT_TRUE(studies.count(s)) << s;
}

}  // namespace
}  // namespace epviz
