// `epviz bench`: bad options exit 2 before any work; a --quick run writes a
// JSON file whose rows are complete and finite where they should be.
#include <gtest/gtest.h>

#include <stb/stb_image.h>
#include <nlohmann/json.hpp>
#include <set>

#include "support/cli.hpp"

namespace epviz {
namespace {

using test::run_epviz;
using test::TempDir;

TEST(BenchCommand, BadOptionsAreUsageErrors) {
  TempDir dir;
  expect_bad_input(run_epviz("bench --quick --cases euler,nope", dir), "--cases");
  expect_bad_input(run_epviz("bench --quick --json " + (dir / "missing/b.json").string(), dir),
                   "--json");
  dir.write("file", "x");
  expect_bad_input(run_epviz("bench --quick --out " + (dir / "file").string(), dir), "--out");
  expect_bad_input(run_epviz("bench --bogus", dir), "--bogus");
  EXPECT_EQ(dir.file_count(), 1u);  // only "file": nothing written
}

// The charts' backend is refused before the studies run, not after them,
// and before the --out folder is made.
TEST(BenchCommand, UnknownGlBackendIsRefusedBeforeAnyStudy) {
  TempDir dir;
  auto r = run_epviz("bench --quick --gl vulkan --out " + (dir / "charts").string(), dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--gl: unknown GL backend 'vulkan' (allowed: auto, egl, osmesa)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("work-precision"), std::string::npos) << "a study ran: " << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(dir.file_count(), 0u);
}

// --job: a body of one's own from a render job; its mistakes are usage
// errors naming the option or the job's key, before any work.
TEST(BenchCommand, JobMistakesAreUsageErrors) {
  TempDir dir;
  auto r = run_epviz("bench --quick --cases custom", dir);
  expect_bad_input(r, "--cases");
  EXPECT_NE(r.err.find("--job"), std::string::npos) << r.err;
  expect_bad_input(run_epviz("bench --quick --job " + (dir / "missing.json").string(), dir),
                   "--job");
  std::ofstream(dir / "bad.json")
      << R"({"simulation": {"inertia": [1, 2, -3], "omega": [0, 1, 0], "gamma": [0, 0, 1]}})";
  expect_bad_input(run_epviz("bench --quick --job " + (dir / "bad.json").string(), dir),
                   "bad.json: key 'simulation.inertia'");
  std::ofstream(dir / "good.json") << R"({"simulation": {"case": "euler"}})";
  std::ofstream(dir / "gallery.json") << R"({"jobs": ["good.json"]})";
  expect_bad_input(run_epviz("bench --quick --job " + (dir / "gallery.json").string(), dir),
                   "single render job");
}

TEST(BenchCommand, JobBodyGetsWorkPrecisionRows) {
  TempDir dir;
  std::ofstream(dir / "top.json") << R"({"simulation": {"inertia": [1, 1.7, 2.3],
      "com": [0.2, -0.1, 0.4], "omega": [0.5, 1.2, -0.3], "gamma": [0, 0.6, 0.8]}})";
  const auto json_path = dir / "bench.json";
  const auto r = run_epviz(
      "bench --quick --job " + (dir / "top.json").string() + " --json " + json_path.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(test::slurp(json_path));
  int custom = 0, presets = 0;
  for (const auto& row : doc.at("rows"))
    if (row.at("study") == "work_precision") (row.at("case") == "custom" ? custom : presets)++;
  EXPECT_GT(custom, 10);
  EXPECT_EQ(presets, 0);  // --job alone studies the job's body only
}

bool is_number(const nlohmann::json& j) { return j.is_number() && std::isfinite(j.get<double>()); }

TEST(BenchCommand, QuickRunWritesCompleteRows) {
  TempDir dir;
  const auto json_path = dir / "bench.json";
  const auto out = dir / "charts";
  const auto r =
      run_epviz("bench --quick --json " + json_path.string() + " --out " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("work-precision: kovalevskaya"), std::string::npos);
  EXPECT_NE(r.out.find("stability 2"), std::string::npos);
  ASSERT_TRUE(std::filesystem::exists(out / "bench.json"));
  EXPECT_EQ(test::slurp(out / "bench.json"), test::slurp(json_path));
  const auto doc = nlohmann::json::parse(test::slurp(json_path));

  const auto& meta = doc.at("metadata");
  EXPECT_GE(meta.at("machine").at("nproc").get<int>(), 1);
  EXPECT_FALSE(meta.at("machine").at("compiler").get<std::string>().empty());
  // Per case, the references agree to well below the smallest resolved error (checked on each reference row).
  EXPECT_LT(meta.at("reference").at("max_self_check").get<double>(), 1e-11);

  const std::vector<std::string> run_fields{
      "impl",    "case",   "formulation", "method",        "accuracy",   "tol",
      "step",    "t_end",  "steps",       "rhs_evals",     "flow_evals", "cpu_ms",
      "repeats", "status", "failure_t",   "failure_reason"};
  const std::map<std::string, std::vector<std::string>> extra{
      {"work_precision", {"error"}},
      {"drift",
       {"drift_gamma_norm2", "drift_C0", "drift_C1", "drift_extra", "budget_evals_per_time"}},
      {"invariant_cost", {"target", "drift_C1", "drift_extra", "reached", "cost"}},
      {"stability_pole", {"variant", "error", "chart_switches", "failure_method"}},
      {"stability_separatrix", {"flip_time", "reference_flip_time", "flip_time_error"}},
      {"stability_sleeping_top", {"reached", "gamma_error"}},
      {"stability_chaos", {"separated", "separation_time", "threshold"}}};
  std::map<std::string, int> count;
  std::set<std::string> cases, methods;
  for (const auto& row : doc.at("rows")) {
    const std::string study = row.at("study");
    ++count[study];
    if (study == "reference") {
      for (const char* k :
           {"case", "method", "check_method", "step", "self_check", "smallest_error", "t_end"})
        ASSERT_TRUE(row.contains(k)) << k;
      EXPECT_TRUE(is_number(row["self_check"]));
      EXPECT_LT(row["self_check"].get<double>() * 10.0, row["smallest_error"].get<double>())
          << row["case"];
      continue;
    }
    if (study == "peer_ratio") {
      for (const char* k :
           {"case", "impl", "method", "error", "peer_cpu_ms", "epviz_dop853_cpu_ms", "ratio"})
        ASSERT_TRUE(row.contains(k)) << k;
      EXPECT_TRUE(is_number(row["ratio"])) << row.dump();
      continue;
    }
    if (study == "stability_max_step") {
      for (const char* k :
           {"case", "method", "max_step", "max_step_over_period", "failing_step", "failure_reason"})
        ASSERT_TRUE(row.contains(k)) << k;
      EXPECT_TRUE(is_number(row["max_step"])) << row.dump();
      continue;
    }
    ASSERT_TRUE(extra.count(study)) << "unexpected study " << study;
    for (const auto& k : run_fields) ASSERT_TRUE(row.contains(k)) << study << " lacks " << k;
    for (const auto& k : extra.at(study)) ASSERT_TRUE(row.contains(k)) << study << " lacks " << k;
    // SciPy's ode('dop853') does not report its step count.
    for (const char* k : {"t_end", "steps", "rhs_evals", "flow_evals", "cpu_ms", "repeats"}) {
      if (k == std::string("steps") && row["method"] == "dop853-ode") continue;
      EXPECT_TRUE(is_number(row[k])) << study << " " << k << ": " << row.dump();
    }
    const bool adaptive = row["accuracy"] == "tol";
    EXPECT_TRUE(is_number(row[adaptive ? "tol" : "step"])) << row.dump();
    const bool ok = row["status"] == "ok";
    EXPECT_EQ(ok, row["failure_t"].is_null()) << row.dump();
    if (study == "work_precision") {
      cases.insert(row["case"]);
      methods.insert(row["method"]);
      // A run may fail (e.g. an implicit solver at the largest step): then it
      // says when and why, and has no error.
      if (ok) {
        EXPECT_TRUE(is_number(row["error"])) << row.dump();
      } else {
        EXPECT_TRUE(is_number(row["failure_t"])) << row.dump();
        EXPECT_FALSE(row["failure_reason"].get<std::string>().empty()) << row.dump();
      }
      EXPECT_TRUE(row.contains("error_resolved")) << row.dump();
    }
    if (study == "drift") {
      for (const char* k : {"drift_gamma_norm2", "drift_C0", "drift_C1", "drift_extra"})
        EXPECT_TRUE(is_number(row[k])) << row.dump();
      EXPECT_GE(row["t_end"].get<double>(), 1e3);
    }
    if (study == "invariant_cost") {
      EXPECT_TRUE(is_number(row["cost"])) << row.dump();
      EXPECT_EQ(row["case"], "kovalevskaya");
      if (row["reached"] == "yes") {
        EXPECT_LT(row["drift_C1"].get<double>(), row["target"].get<double>()) << row.dump();
        EXPECT_LT(row["drift_extra"].get<double>(), row["target"].get<double>()) << row.dump();
      }
    }
    if (study == "stability_pole" && ok) {
      EXPECT_TRUE(is_number(row["error"])) << row.dump();
    }
  }
  EXPECT_EQ(cases.size(), 6u);
  EXPECT_GE(methods.size(), 7u);
  // The peers ran on the same problem (GSL and Boost.Odeint are installed by scripts/setup.sh).
  EXPECT_GT(count["peer_ratio"], 0);

  // The charts, drawn by epviz itself: present and not blank (a white page with
  // dark ink: axes, labels and series).
  for (const char* name :
       {"work_precision_kovalevskaya.png", "drift_kovalevskaya.png", "stability.png"}) {
    const auto png = out / name;
    ASSERT_TRUE(std::filesystem::exists(png)) << png;
    int w = 0, h = 0, n = 0;
    unsigned char* pixels = stbi_load(png.c_str(), &w, &h, &n, 4);
    ASSERT_NE(pixels, nullptr) << png;
    long dark = 0, coloured = 0;
    for (long i = 0; i < long(w) * h; ++i) {
      const unsigned char* p = pixels + 4 * i;
      dark += p[0] < 100 && p[1] < 100 && p[2] < 100;
      coloured += std::abs(int(p[0]) - int(p[2])) > 60;
    }
    stbi_image_free(pixels);
    EXPECT_GT(dark, 2000) << name;
    if (std::string(name) != "stability.png") {
      EXPECT_GT(coloured, 200) << name << ": no series drawn";
    }
  }
  EXPECT_EQ(count["reference"], 6);
  EXPECT_GE(count["invariant_cost"], 9);
  for (const char* s :
       {"work_precision", "drift", "invariant_cost", "stability_max_step", "stability_pole",
        "stability_separatrix", "stability_sleeping_top", "stability_chaos"})
    EXPECT_GT(count[s], 0) << s;
}

}  // namespace
}  // namespace epviz
