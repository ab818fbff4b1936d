// A run that has lost the motion is a numerical failure in `epviz simulate`
// and `epviz render` alike: exit 3 at the first output time whose energy (or
// |gamma|^2) drift exceeds the limit (`--max-drift`, `simulation.max_drift`,
// default 1), with nothing non-finite written and nothing drawn after it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

// The Lagrange preset's body (epviz cases) spun up to a fast sleeping top.
constexpr double kInertia[3] = {1.0, 1.0, 0.5};
constexpr double kCom[3] = {0.0, 0.0, 1.0};
constexpr double kWeight = 1.0;
const std::string kTilt = std::to_string(std::sin(5.0 * std::numbers::pi / 180.0)) + ",0," +
                          std::to_string(std::cos(5.0 * std::numbers::pi / 180.0));

std::string fast_top_args(const std::string& extra) {
  return "simulate --inertia 1,1,0.5 --com 0,0,1 --weight 1 --omega 0,0,50 --gamma " + kTilt +
         " --normalize-gamma --formulation riccati --method rk4 --step 2 --t-end 40 --samples 20 " +
         extra;
}

struct Row {
  double t;
  double omega[3], gamma[3];
};

// Every field of the CSV, each of which must be empty (a, b at the south
// pole; the fourth integral of a custom body) or a finite number.
std::vector<Row> read_finite_rows(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("t,omega1,omega2,omega3,gamma1,gamma2,gamma3,", 0), 0u) << line;
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream fields(line);
    std::string field;
    int column = 0;
    while (std::getline(fields, field, ',')) {
      ++column;
      if (field.empty()) {
        EXPECT_TRUE(column == 8 || column == 9 || column == 13) << "empty column " << column;
        v.push_back(0.0);
        continue;
      }
      char* end = nullptr;
      const double x = std::strtod(field.c_str(), &end);
      EXPECT_EQ(*end, '\0') << "not a number: '" << field << "' in " << line;
      EXPECT_TRUE(std::isfinite(x)) << "'" << field << "' in " << line;
      v.push_back(x);
    }
    if (v.size() < 7) {
      ADD_FAILURE() << "short row: " << line;
      continue;
    }
    rows.push_back({v[0], {v[1], v[2], v[3]}, {v[4], v[5], v[6]}});
  }
  return rows;
}

// The relative energy drift of a row, computed here from the body and the
// first row: C1 = 1/2 sum I_i w_i^2 + P r.gamma against
// max(|C1(0)|, 1/2 sum I_i w_i(0)^2 + P |r| |gamma(0)|).
double energy_drift(const Row& row, const Row& first) {
  auto energy = [](const Row& r, bool potential) {
    double e = 0.0;
    for (int i = 0; i < 3; ++i) e += 0.5 * kInertia[i] * r.omega[i] * r.omega[i];
    if (potential)
      for (int i = 0; i < 3; ++i) e += kWeight * kCom[i] * r.gamma[i];
    return e;
  };
  const double e0 = energy(first, true);
  const double g0 = std::sqrt(first.gamma[0] * first.gamma[0] + first.gamma[1] * first.gamma[1] +
                              first.gamma[2] * first.gamma[2]);
  const double scale = std::max(std::abs(e0), energy(first, false) + kWeight * 1.0 * g0);
  return std::abs(energy(row, true) - e0) / scale;
}

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(test::slurp(p)); }

TEST(MaxDrift, FastTopRiccatiRk4WritesOnlyFiniteRowsAndExitsThree) {
  test::TempDir dir;
  const auto r = test::run_epviz(fast_top_args("--csv " + (dir / "s.csv").string() +
                                               " --report-json " + (dir / "r.json").string()),
                                 dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const auto rows = read_finite_rows(dir / "s.csv");
  ASSERT_FALSE(rows.empty());
  // One line on stderr: the time, the method, the fact and the advice.
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("rk4 failed at t = "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lost the motion: relative energy drift"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("above the limit 1;"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--step"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("nan"), std::string::npos) << r.err;
  const auto report = read_json(dir / "r.json");
  EXPECT_EQ(report["failure_kind"], "lost_motion");
  EXPECT_EQ(report["samples_written"], rows.size());
  EXPECT_GT(report["failure"]["t"].get<double>(), rows.back().t);
}

TEST(MaxDrift, FailsAtTheFirstRowWhoseDriftExceedsTheLimit) {
  // The same run with a limit that never stops it: its rows are the oracle's
  // data, and the drift of each is computed here.
  test::TempDir dir;
  const auto all =
      test::run_epviz(fast_top_args("--max-drift 1e300 --csv " + (dir / "all.csv").string() +
                                    " --report-json " + (dir / "all.json").string()),
                      dir);
  ASSERT_EQ(all.exit_code, 3) << all.err;
  const auto unlimited = read_finite_rows(dir / "all.csv");
  ASSERT_GT(unlimited.size(), 2u);
  std::size_t first_lost = unlimited.size();
  for (std::size_t i = 0; i < unlimited.size() && first_lost == unlimited.size(); ++i)
    if (energy_drift(unlimited[i], unlimited[0]) > 1.0) first_lost = i;
  ASSERT_LT(first_lost, unlimited.size()) << "no row above the default limit";

  for (const std::string& limit : {std::string(), std::string("--max-drift 1e4")}) {
    SCOPED_TRACE(limit.empty() ? "default limit" : limit);
    const double max_drift = limit.empty() ? 1.0 : 1e4;
    std::size_t expected = unlimited.size();
    for (std::size_t i = 0; i < unlimited.size() && expected == unlimited.size(); ++i)
      if (energy_drift(unlimited[i], unlimited[0]) > max_drift) expected = i;
    ASSERT_LT(expected, unlimited.size());

    const auto r = test::run_epviz(fast_top_args(limit + " --csv " + (dir / "s.csv").string() +
                                                 " --report-json " + (dir / "r.json").string()),
                                   dir);
    EXPECT_EQ(r.exit_code, 3) << r.err;
    const auto rows = read_finite_rows(dir / "s.csv");
    ASSERT_EQ(rows.size(), expected);
    for (const auto& row : rows) EXPECT_LE(energy_drift(row, rows[0]), max_drift);
    const auto report = read_json(dir / "r.json");
    EXPECT_EQ(report["failure_kind"], "lost_motion");
    EXPECT_DOUBLE_EQ(report["failure"]["t"].get<double>(), unlimited[expected].t);
  }

  // Without the limit the run goes on until the state is no longer finite:
  // a failure too, with no non-finite row written.
  EXPECT_EQ(read_json(dir / "all.json")["failure_kind"], "non_finite");
  EXPECT_GT(unlimited.size(), first_lost + 1);
}

TEST(MaxDrift, AnAccurateRunIsUntouched) {
  test::TempDir dir;
  const auto r = test::run_epviz(
      "simulate --case kovalevskaya --t-end 5 --samples 50 --csv " + (dir / "s.csv").string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_finite_rows(dir / "s.csv").size(), 51u);
}

TEST(MaxDrift, BadLimitsAreRejected) {
  test::TempDir dir;
  for (const char* bad : {"0", "-1", "abc", "nan"}) {
    const auto r = test::run_epviz("simulate --case euler --max-drift " + std::string(bad) +
                                       " --csv " + (dir / "s.csv").string(),
                                   dir);
    SCOPED_TRACE(bad);
    test::expect_bad_input(r, "--max-drift");
    EXPECT_FALSE(fs::exists(dir / "s.csv"));
  }
  std::ofstream(dir / "job.json") << R"({"case": "euler", "max_drift": -2})";
  const auto r = test::run_epviz("simulate --job " + (dir / "job.json").string(), dir);
  test::expect_bad_input(r, "job.json: key 'max_drift'");
}

// A render job of the same fast top, direct formulation, with RK4 just beyond
// its stability limit (step 0.058, 50 x 0.058 = 2.9 > 2.83): |gamma| grows by
// about a fifth a step. 10 frames, 8 samples between two, one step per sample.
constexpr double kRenderTEnd = 72 * 0.058;
nlohmann::json coarse_render_job(const fs::path& out) {
  return {
      {"simulation",
       {{"inertia", {1, 1, 0.5}},
        {"com", {0, 0, 1}},
        {"weight", 1},
        {"omega", {0, 0, 50}},
        {"gamma",
         {std::sin(5.0 * std::numbers::pi / 180.0), 0, std::cos(5.0 * std::numbers::pi / 180.0)}},
        {"formulation", "direct"},
        {"method", "rk4"},
        {"step", 0.058},
        {"t_end", kRenderTEnd}}},
      {"width", 160},
      {"height", 120},
      {"fps", 5},
      {"duration", 2},
      {"output", {{"dir", out.string()}, {"format", "png"}, {"name", "f"}}}};
}

TEST(MaxDrift, RenderStopsAtTheFailureAndDrawsNothingAfterIt) {
  test::TempDir dir;
  const auto job = coarse_render_job(dir / "frames");
  std::ofstream(dir / "job.json") << job.dump(2);
  const auto r = test::run_epviz(
      "render " + (dir / "job.json").string() + " --report-json " + (dir / "r.json").string(), dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("rk4 failed at t = "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lost the motion"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("simulation.step"), std::string::npos) << r.err;
  const auto report = read_json(dir / "r.json");
  EXPECT_EQ(report["failure_kind"], "lost_motion");
  const double t_fail = std::strtod(
      r.err.substr(r.err.find("failed at t = ") + std::string("failed at t = ").size()).c_str(),
      nullptr);
  // Frame i shows t = t_end * i / (frames - 1): every frame before the
  // failure is drawn, none at or after it.
  const int frames = 10;
  const double t_end = kRenderTEnd;
  int drawn = 0;
  for (int i = 0; i < frames; ++i) {
    const double t = t_end * i / (frames - 1);
    const bool exists = fs::exists(dir / "frames" / ("f_000" + std::to_string(i) + ".png"));
    EXPECT_EQ(exists, t < t_fail) << "frame " << i << " at t = " << t << ", failure at " << t_fail;
    drawn += exists;
  }
  EXPECT_GT(drawn, 0);
  EXPECT_LT(drawn, frames);
  EXPECT_EQ(report["frames_drawn"], drawn);

  // The job's own limit lets it go further.
  auto lenient = job;
  lenient["simulation"]["max_drift"] = 1e300;
  lenient["output"]["dir"] = (dir / "lenient").string();
  std::ofstream(dir / "lenient.json") << lenient.dump(2);
  const auto l = test::run_epviz(
      "render " + (dir / "lenient.json").string() + " --report-json " + (dir / "l.json").string(),
      dir);
  EXPECT_EQ(l.exit_code, 3) << l.err;
  EXPECT_EQ(read_json(dir / "l.json")["failure_kind"], "non_finite") << l.err;
  EXPECT_GT(read_json(dir / "l.json")["frames_drawn"].get<int>(), drawn);
}

}  // namespace
}  // namespace epviz
