// `epviz section` as a user runs it: the CSV it writes, bad section files
// refused before any work (exit 2, one line naming the key), and a lost orbit
// reported as a numerical failure (exit 3) with nothing written.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "io/bad_input.hpp"
#include "physics/admissible.hpp"
#include "section/section_csv.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"
#include "support/cli.hpp"

namespace epviz::test {
namespace {

namespace fs = std::filesystem;

CliResult run_section_file(const TempDir& d, const std::string& text) {
  std::ofstream(d / "s.section.json") << text;
  return run_epviz("section " + (d / "s.section.json").string() + " -j 2", d);
}

TEST(SectionCommand, WritesOneRowPerCrossingWithTheStateAndItsIntegrals) {
  TempDir d;
  const std::string csv = (d / "k.csv").string();
  const auto r =
      run_section_file(d, R"({"case": "kovalevskaya", "level": {"energy": 2, "area": 0.5},
      "orbits": 3, "crossings": 4, "csv": ")" +
                              csv + "\"}");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(slurp(csv));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "orbit,crossing,t,omega1,omega2,omega3,gamma1,gamma2,gamma3,energy,area,"
            "gamma_norm_error,extra_integral");
  std::vector<std::string> keys;
  while (std::getline(in, line)) keys.push_back(line.substr(0, line.find(',', 2)));
  EXPECT_EQ(keys, (std::vector<std::string>{"1,1", "1,2", "1,3", "1,4", "2,1", "2,2", "2,3", "2,4",
                                            "3,1", "3,2", "3,3", "3,4"}));
}

// The shipped section files run as they are, and draw their crossings.
TEST(SectionCommand, ShippedSectionFilesRunAndDrawTheirCrossings) {
  for (const std::string name : {"kovalevskaya", "generic", "kovalevskaya_andoyer"}) {
    SCOPED_TRACE(name);
    TempDir d;
    const fs::path shipped = fs::path(EPVIZ_SOURCE_DIR) / "render_jobs" / (name + ".section.json");
    auto job = nlohmann::json::parse(slurp(shipped));
    for (const char* key : {"csv", "png", "svg"})
      job[key] = (d / fs::path(job[key].get<std::string>()).filename()).string();
    job["crossings"] = 20;  // the picture, not the full run
    const auto r = run_section_file(d, job.dump());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(line_count(slurp(job["csv"].get<std::string>())), 1u + 16u * 20u);
    EXPECT_EQ(slurp(job["png"].get<std::string>()).substr(1, 3), "PNG");
    EXPECT_NE(slurp(job["svg"].get<std::string>()).find("<svg"), std::string::npos);
  }
}

// A shipped section taken by its name writes its files where the user is,
// not beside the shipped file; "pdf" draws the same panels as a PDF.
TEST(SectionCommand, AShippedSectionRunsByItsNameAndDrawsAPdf) {
  TempDir d;
  const std::string in_d = "cd " + d.path().string() + " &&";
  const auto r = run_epviz("section kovalevskaya_methods -j 2", d, in_d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(line_count(slurp(d / "kovalevskaya_methods.section.csv")), 1u + 8u * 300u * 3u);
  EXPECT_EQ(slurp(d / "kovalevskaya_methods.section.png").substr(1, 3), "PNG");
  EXPECT_FALSE(
      fs::exists(fs::path(EPVIZ_SOURCE_DIR) / "render_jobs" / "kovalevskaya_methods.section.csv"));
  const auto missing = run_epviz("section no_such_section", d, in_d);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no such section file, nor a shipped section"), std::string::npos)
      << missing.err;

  auto job = nlohmann::json::parse(
      slurp(fs::path(EPVIZ_SOURCE_DIR) / "render_jobs" / "kovalevskaya.section.json"));
  job.erase("png");
  job.erase("svg");
  job["csv"] = (d / "k.csv").string();
  job["pdf"] = (d / "k.pdf").string();
  job["crossings"] = 20;
  const auto pdf = run_section_file(d, job.dump());
  ASSERT_EQ(pdf.exit_code, 0) << pdf.err;
  const std::string bytes = slurp(d / "k.pdf");
  EXPECT_EQ(bytes.substr(0, 5), "%PDF-");
  EXPECT_GT(bytes.size(), 2000u);
  // Named like another output, it is refused before any work.
  job["pdf"] = job["csv"];
  fs::remove(d / "k.csv");
  const auto same = run_section_file(d, job.dump());
  EXPECT_EQ(same.exit_code, 2) << same.err;
  EXPECT_FALSE(fs::exists(d / "k.csv"));
}

// Directions of gamma the level cannot reach carry no orbit, and the summary
// says how many: at C1 = 0.5, C0 = 0.5 the Kovalevskaya body's potential
// gamma1 leaves out the directions near gamma1 = 1 (C1 - V < T_min there).
TEST(SectionCommand, SaysHowManyDirectionsLieBelowTheLevel) {
  TempDir d;
  const std::string csv = (d / "k.csv").string();
  const auto r = run_section_file(d, R"({"case": "kovalevskaya", "level": {"energy": 0.5,
      "area": 0.5}, "orbits": 40, "crossings": 2, "csv": ")" +
                                         csv + "\"}");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto kept =
      physics::level_states(physics::preset(physics::Case::kovalevskaya).body, {0.5, 0.5}, 40);
  ASSERT_FALSE(kept.rejected.empty());
  std::string expected = std::to_string(kept.states.size());
  expected += " orbits (";
  expected += std::to_string(kept.rejected.size());
  expected += " of 40 directions of gamma lie below the level)";
  EXPECT_NE(r.out.find(expected), std::string::npos) << r.out;
}

// Just above the least energy at C0 = 0.5 (-0.9375 for this body) only a
// small cap of directions carries states, which a grid over the sphere of
// `orbits` directions misses: the section starts its orbits there. Below it
// the refusal gives the least energy to full precision.
TEST(SectionCommand, LevelsNearTheLeastEnergyAreReachedAndTheLeastIsPrintedWhole) {
  TempDir d;
  const auto& body = physics::preset(physics::Case::kovalevskaya).body;
  const double least = physics::minimum_energy(body, 0.5).energy;
  for (double energy : {least + 1e-6, -0.9, -0.86}) {
    const std::string csv = (d / "near.csv").string();
    char level[80];
    std::snprintf(level, sizeof level, R"("level": {"energy": %.17g, "area": 0.5})", energy);
    const auto r =
        run_section_file(d, std::string(R"({"case": "kovalevskaya", )") + level +
                                R"(, "orbits": 8, "crossings": 3, "csv": ")" + csv + "\"}");
    ASSERT_EQ(r.exit_code, 0) << energy << ": " << r.err;
    EXPECT_GT(test::line_count(test::slurp(csv)), 1u) << energy;
  }
  const auto r = run_section_file(d, R"({"case": "kovalevskaya", "level": {"energy": -0.95,
      "area": 0.5}, "orbits": 8, "crossings": 3, "csv": "x.csv"})");
  ASSERT_EQ(r.exit_code, 2) << r.err;
  const auto at = r.err.find("least energy at this area is ");
  ASSERT_NE(at, std::string::npos) << r.err;
  const double printed = std::stod(r.err.substr(at + 29));
  EXPECT_EQ(printed, least) << r.err;
}

struct BadFile {
  std::string name, text, must_name;
};

TEST(SectionCommand, BadFilesAreRefusedBeforeAnyWork) {
  const std::vector<BadFile> cases{
      {"unknown key", R"({"case": "generic", "level": {"energy": 2, "area": 1}, "orbits": 2,
         "colour": 1, "csv": "x.csv"})",
       "colour"},
      {"no case", R"({"level": {"energy": 2, "area": 1}, "orbits": 2, "csv": "x.csv"})", "case"},
      {"unknown case", R"({"case": "top", "level": {"energy": 2, "area": 1}, "orbits": 2,
         "csv": "x.csv"})",
       "kovalevskaya"},
      {"level and states", R"({"case": "generic", "level": {"energy": 2, "area": 1},
         "orbits": 2, "states": [{"omega": [1, 0, 0], "gamma": [0, 0, 1]}], "csv": "x.csv"})",
       "'level'"},
      {"no orbits", R"({"case": "generic", "level": {"energy": 2, "area": 1}, "csv": "x.csv"})",
       "'orbits'"},
      {"unknown method", R"({"case": "generic", "level": {"energy": 2, "area": 1},
         "orbits": 2, "method": "euler", "csv": "x.csv"})",
       "dop853"},
      {"too many fixed steps", R"({"case": "generic", "level": {"energy": 2, "area": 1},
         "orbits": 2, "method": "rk4", "step": 1e-6, "t_end": 1e6, "csv": "x.csv"})",
       "'step'"},
      {"unknown surface", R"({"case": "generic", "level": {"energy": 2, "area": 1}, "orbits": 2,
         "section": {"function": "a"}, "csv": "x.csv"})",
       "gamma3"},
      {"gamma not unit", R"({"case": "generic", "states": [{"omega": [1, 0, 0],
         "gamma": [0, 0, 2]}], "csv": "x.csv"})",
       "states[0]"},
      {"omega too large", R"({"case": "generic", "states": [{"omega": [1, 0, 0],
         "gamma": [0, 0, 1]}, {"omega": [0, 2e6, 0], "gamma": [0, 0, 1]}], "csv": "x.csv"})",
       "states[1]"},
      {"below the level", R"({"case": "generic", "level": {"energy": -5, "area": 1},
         "orbits": 2, "csv": "x.csv"})",
       "least energy"},
      {"too many crossings", R"({"case": "generic", "level": {"energy": 2, "area": 1},
         "orbits": 100000, "crossings": 1000, "csv": "x.csv"})",
       "'crossings'"},
      {"no csv", R"({"case": "generic", "level": {"energy": 2, "area": 1}, "orbits": 2})", "'csv'"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    TempDir d;
    expect_bad_input(run_section_file(d, c.text), c.must_name);
  }
}

// Two keys naming one file: the picture would replace the CSV written just
// before it. Refused with the outputs' check, before any orbit runs.
TEST(SectionJob, OutputsNamingOneFileAreRefused) {
  TempDir d;
  const fs::path file = d / "s.section.json";
  const std::string csv = (d / "x.csv").string();
  const std::string same_csv = (d / "." / "x.csv").string();  // another spelling
  nlohmann::json png_on_csv = {{"csv", csv}, {"png", same_csv}};
  nlohmann::json svg_on_csv = {{"csv", csv}, {"png", (d / "y.png").string()}, {"svg", csv}};
  for (auto& [outputs, must_name] : {std::pair{png_on_csv, "'png'"}, {svg_on_csv, "'svg'"}}) {
    SCOPED_TRACE(must_name);
    nlohmann::json text = outputs;
    text["case"] = "generic";
    text["level"] = {{"energy", 2}, {"area", 1}};
    text["orbits"] = 2;
    std::ofstream(file) << text.dump();
    const section::SectionJob job = section::read_section_job(file);
    try {
      section::check_outputs(job);
      ADD_FAILURE() << "accepted";
    } catch (const io::BadInput& e) {
      EXPECT_NE(std::string(e.what()).find(must_name), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("same file"), std::string::npos) << e.what();
    }
  }
}

TEST(SectionCommand, ALostOrbitIsANumericalFailureAndNothingIsWritten) {
  TempDir d;
  const std::string csv = (d / "g.csv").string();
  // A loose tolerance cannot keep the energy to 1e-13 for 200 crossings.
  const auto r = run_section_file(d, R"({"case": "generic", "level": {"energy": 2, "area": 1},
      "orbits": 2, "crossings": 200, "tol": 1e-5, "max_drift": 1e-13, "csv": ")" +
                                         csv + "\"}");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("orbits lost"), std::string::npos) << r.err;
  EXPECT_EQ(line_count(r.err), 1u) << r.err;
  EXPECT_FALSE(fs::exists(csv));
}

// The advice follows what went wrong and how the method steps: a fixed-step
// method has no "tol" to tighten, and a run out of steps needs to be shorter.
TEST(SectionCommand, ALostOrbitsAdviceFitsItsMethodAndFailure) {
  section::SectionJob job;
  job.case_id = physics::Case::generic;
  job.methods = {{sim::Method::dop853, 1e-10, 0.01}, {sim::Method::rk4, 1e-10, 0.05}};
  const auto advice = [&](std::size_t method, numerics::FailureKind kind) {
    section::OrbitResult lost;
    lost.orbit = 1;
    lost.method = method;
    lost.failure = numerics::Failure{1.0, "x", kind, "what happened"};
    const std::string line = section::lost_orbits_line(job, {lost});
    return line.substr(line.find("what happened; ") + 15);
  };
  using numerics::FailureKind;
  EXPECT_EQ(advice(0, FailureKind::lost_motion).rfind("tighten \"tol\"", 0), 0u);
  const std::string fixed = advice(1, FailureKind::lost_motion);
  EXPECT_EQ(fixed.rfind("use a smaller \"step\"", 0), 0u) << fixed;
  EXPECT_EQ(fixed.find("tol"), std::string::npos) << fixed;
  EXPECT_EQ(advice(1, FailureKind::non_finite).rfind("use a smaller \"step\"", 0), 0u);
  for (std::size_t method : {0u, 1u}) {
    const std::string budget = advice(method, FailureKind::step_budget);
    EXPECT_NE(budget.find("more steps than one run may take: shorten it"), std::string::npos)
        << budget;
    EXPECT_EQ(budget.find("tighten"), std::string::npos) << budget;
  }
}

// An unknown GL backend is bad input like any other: refused before the
// orbits run and the CSV is written, not when the picture is drawn.
TEST(SectionCommand, AnUnknownGlBackendIsRefusedBeforeTheCsvIsWritten) {
  TempDir d;
  const std::string csv = (d / "g.csv").string();
  const nlohmann::json section = {{"case", "generic"}, {"level", {{"energy", 2}, {"area", 1}}},
                                  {"orbits", 1},       {"crossings", 3},
                                  {"csv", csv},        {"svg", (d / "g.svg").string()}};
  std::ofstream(d / "s.section.json") << section.dump();
  const auto r = run_epviz("section " + (d / "s.section.json").string() + " --gl bogus", d);
  expect_bad_input(r, "--gl");
  EXPECT_FALSE(fs::exists(csv)) << "the CSV was written before --gl was checked";
}

TEST(SectionCsv, LeavesALostOrbitOut) {
  section::SectionJob job;
  job.case_id = physics::Case::generic;
  job.body = physics::preset(job.case_id).body;
  section::OrbitResult kept, lost;
  kept.orbit = 1;
  kept.crossings.push_back({1, 0.5, physics::Vector3d(1, 0, 0), physics::Vector3d(0, 0, 1)});
  lost.orbit = 2;
  lost.crossings = kept.crossings;
  lost.failure = numerics::Failure{};
  const std::string text = section::crossings_csv(job, {kept, lost});
  EXPECT_EQ(line_count(text), 2u) << text;
  EXPECT_EQ(text.find("\n2,"), std::string::npos) << text;
}

}  // namespace
}  // namespace epviz::test

namespace epviz::test {
namespace {

// The extra_integral column's spread over each orbit of each method, from the CSV.
std::map<std::string, double> k_spread_by_method(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("method,orbit,crossing,", 0), 0u) << line;
  std::map<std::string, std::pair<double, double>> range;  // by "method,orbit"
  std::map<std::string, double> spread;
  while (std::getline(in, line)) {
    const std::string method = line.substr(0, line.find(','));
    const std::string run = line.substr(0, line.find(',', method.size() + 1));
    const double k = std::stod(line.substr(line.rfind(',') + 1));
    auto [it, fresh] = range.try_emplace(run, k, k);
    it->second = {std::min(it->second.first, k), std::max(it->second.second, k)};
    spread[method] = std::max(spread[method], it->second.second - it->second.first);
  }
  return spread;
}

// Each method of a section runs every orbit with its own setting: rk4 at a
// coarse step lets Kovalevskaya's K wander (its crossings leave the invariant
// curves), dop853 keeps it to the oracle's 1e-9.
TEST(SectionCommand, EachMethodOfASectionRunsWithItsOwnSetting) {
  TempDir d;
  const std::string csv = (d / "m.csv").string();
  const auto r = run_section_file(d, R"({"case": "kovalevskaya", "level": {"energy": 2,
      "area": 0.5}, "orbits": 3, "crossings": 40, "max_drift": 0.1,
      "methods": [{"method": "rk4", "step": 0.1}, {"method": "dop853", "tol": 1e-11}],
      "png": ")" + (d / "m.png").string() +
                                         R"(", "svg": ")" + (d / "m.svg").string() +
                                         R"(", "csv": ")" + csv + "\"}");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("3 orbits x 2 methods, 240 crossings"), std::string::npos) << r.out;
  const auto spread = k_spread_by_method(slurp(csv));
  ASSERT_EQ(spread.size(), 2u);
  const double rk4 = spread.at("rk4 step 0.1"), dop853 = spread.at("dop853 tol 1e-11");
  EXPECT_LT(dop853, 1e-8);
  EXPECT_GT(rk4, 1e3 * dop853);
  // Both pictures hold the two panels side by side (760 wide each, 16 apart).
  const std::string png = slurp(d / "m.png");
  ASSERT_EQ(png.substr(1, 3), "PNG");
  const auto byte = [&](std::size_t i) { return unsigned(static_cast<unsigned char>(png[i])); };
  EXPECT_EQ((byte(18) << 8) | byte(19), 1536u);  // the header's width
  EXPECT_NE(slurp(d / "m.svg").find("width=\"1536px\""), std::string::npos);
}

TEST(SectionCommand, BadMethodListsAreRefusedBeforeAnyWork) {
  const std::vector<BadFile> cases{
      {"method and methods", R"({"case": "generic", "level": {"energy": 2, "area": 1},
         "orbits": 2, "method": "rk4", "methods": [{"method": "dop853"}], "csv": "x.csv"})",
       "'methods'"},
      {"twice", R"({"case": "generic", "level": {"energy": 2, "area": 1}, "orbits": 2,
         "methods": [{"method": "rk4", "step": 0.1}, {"method": "rk4", "step": 0.1}],
         "csv": "x.csv"})",
       "methods[1]"},
      {"no method", R"({"case": "generic", "level": {"energy": 2, "area": 1}, "orbits": 2,
         "methods": [{"tol": 1e-8}], "csv": "x.csv"})",
       "methods[0]"},
      {"unknown key", R"({"case": "generic", "level": {"energy": 2, "area": 1}, "orbits": 2,
         "methods": [{"method": "rk4", "colour": 1}], "csv": "x.csv"})",
       "colour"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    TempDir d;
    expect_bad_input(run_section_file(d, c.text), c.must_name);
  }
}

}  // namespace
}  // namespace epviz::test
