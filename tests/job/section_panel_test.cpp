// A render job's "section": read with a section file's names, defaults and
// checks, refused with one line naming the key; the panel's dots at the last
// frame are the crossings `epviz section` finds for the same run, and they
// come in frame by frame.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "job/job_plan.hpp"
#include "job/schema.hpp"
#include "scene/frame_source.hpp"
#include "scene/plan.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"
#include "section_refusal.hpp"
#include "sim/rhs_tally.hpp"
#include "sim/section.hpp"
#include "sim/trajectory.hpp"
#include "support/cli.hpp"

namespace epviz {
namespace {

using sim::StateComponent;
using test::TempDir;

job::RenderJob render_job(const nlohmann::json& j) {
  const auto d = job::read_job(j, "job.json");
  return {"job.json", d.simulation, d.runs, d.scene, d.output};
}

nlohmann::json kovalevskaya_job(const nlohmann::json& section) {
  return {{"simulation",
           {{"case", "kovalevskaya"},
            {"t_end", 240},  // some 10 crossings on each sheet
            {"method", "dop853"},
            {"tol", 1e-10},
            {"omega", {1.0, 0.8, 0.6}},
            {"gamma", {0.6, 0.0, 0.8}}}},
          {"section", section},
          {"width", 320},
          {"height", 180},
          {"fps", 10},
          {"duration", 3}};
}

TEST(SectionPanelKey, ReadsTheSectionFilesKeysAndDefaultsAndWritesThemBack) {
  const auto d = job::read_job(kovalevskaya_job(nlohmann::json::object()), "job.json");
  ASSERT_TRUE(d.scene.section);
  // The section file's defaults: gamma3 = 0 upward, plotted at (gamma1, omega3).
  EXPECT_EQ(d.scene.section->surface.function, StateComponent::gamma3);
  EXPECT_EQ(d.scene.section->surface.direction, sim::CrossingDirection::upward);
  EXPECT_EQ(d.scene.section->coords, section::default_coords(StateComponent::gamma3));
  const auto given = job::read_job(kovalevskaya_job({{"function", "omega3"},
                                                     {"value", 0.5},
                                                     {"direction", "both"},
                                                     {"coords", {"gamma1", "gamma2"}}}),
                                   "job.json");
  const auto back = job::read_job(nlohmann::json::parse(job::write_job(given).dump()), "job.json");
  for (const auto* doc : {&given, &back}) {
    ASSERT_TRUE(doc->scene.section);
    EXPECT_EQ(doc->scene.section->surface.function, StateComponent::omega3);
    EXPECT_EQ(doc->scene.section->surface.value, 0.5);
    EXPECT_EQ(doc->scene.section->surface.direction, sim::CrossingDirection::both);
    EXPECT_EQ(doc->scene.section->coords[1], StateComponent::gamma2);
  }
  // Another surface's default axes are the first two components it leaves free.
  const auto other = job::read_job(kovalevskaya_job({{"function", "omega1"}}), "job.json");
  EXPECT_EQ(other.scene.section->coords[0], StateComponent::omega2);
  EXPECT_FALSE(job::read_job({{"simulation", {{"case", "euler"}}}}, "job.json").scene.section);
}

TEST(SectionPanelKey, BadValuesExitTwoNamingTheKey) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"function": "gamma4"})", "key 'section.function'"},
      {R"({"value": "zero"})", "key 'section.value'"},
      {R"({"direction": "up"})", "key 'section.direction'"},
      {R"({"coords": ["gamma1"]})", "key 'section.coords'"},
      {R"({"coords": ["gamma1", "theta"]})", "key 'section.coords'"},
      {R"({"surface": "gamma3"})", "section.surface"},
      {R"({"sheet": "gamma2 = 0"})", "key 'section.sheet'"},
      {R"({"sheet": "gamma2"})", "key 'section.sheet'"},
      {R"({"sheet": "gamma3 > 0"})", "key 'section.sheet'"},
      {R"({"sheet": "omega3 < 0"})", "key 'section.sheet'"},
      {R"({"sheet": 1})", "key 'section.sheet'"},
      {R"({"sheets": "gamma2"})", "section.sheets"},
      {R"(3)", "key 'section'"},
  };
  for (const auto& [section, named] : cases) test::expect_section_refused(section, named);
}

// The same run through `epviz section`'s code: one orbit from the job's
// start, with its body, method, tolerance and surface.
std::vector<sim::Crossing> section_code_crossings(const sim::RunSpec& run,
                                                  const sim::SectionSurface& surface) {
  section::SectionJob s;
  s.case_id = run.case_id;
  s.body = run.body;
  s.states = {run.initial};
  s.orbits = 1;
  s.crossings = 1000000;
  s.t_end = run.t_end;
  s.surface = surface;
  s.methods = {{run.method, run.tol, run.step}};
  s.max_drift = run.max_drift;
  const auto results = section::run_section(s, s.states, 1);
  EXPECT_EQ(results.size(), 1u);
  EXPECT_FALSE(results.front().failure);
  return results.front().crossings;
}

// The oracle of the panel's sheet: the crossings whose gamma2, read off
// each crossing's own state, has the sign `sign` (or is 0, the fold, which
// both sheets share).
std::vector<sim::Crossing> with_gamma2_sign(const std::vector<sim::Crossing>& all, int sign) {
  std::vector<sim::Crossing> kept;
  for (const auto& c : all)
    if (sign * c.gamma.y() >= 0.0) kept.push_back(c);
  return kept;
}

TEST(SectionPanel, LastFrameShowsTheCrossingsOfEpvizSectionAndFillsFrameByFrame) {
  const auto job = render_job(kovalevskaya_job({{"coords", {"gamma1", "omega3"}}}));
  const auto plan = job::plan_job(job);
  scene::FrameSource source(plan, job.scene);
  std::size_t previous = 0, grew = 0;
  scene::Frame last;
  for (int i = 0; i < source.frame_count(); ++i) {
    last = source.frame(i);
    ASSERT_TRUE(last.section);
    ASSERT_EQ(last.section->runs.size(), 1u);
    const std::size_t n = last.section->runs.front().size();
    EXPECT_GE(n, previous) << "frame " << i;
    grew += n > previous ? 1 : 0;
    previous = n;
  }
  // Filling as the orbit runs: new dots in many frames, not all at once.
  EXPECT_GT(grew, 5u);
  const auto all = section_code_crossings(plan.run, job.scene.section->surface);
  // The default sheet of gamma3 = 0 at (gamma1, Omega3): gamma2 > 0; the
  // others are counted, not drawn.
  const auto expected = with_gamma2_sign(all, 1);
  ASSERT_GT(expected.size(), 10u);
  ASSERT_GT(all.size() - expected.size(), 3u) << "the run crosses both sheets";
  EXPECT_EQ(last.section->hidden, all.size() - expected.size());
  EXPECT_EQ(last.section->title, "γ₃ = 0, upward, γ₂ > 0");
  EXPECT_EQ(last.section->note,
            std::to_string(all.size() - expected.size()) + " crossings on γ₂ < 0 not drawn");
  const auto& dots = last.section->runs.front();
  ASSERT_EQ(dots.size(), expected.size());
  for (std::size_t k = 0; k < dots.size(); ++k) {
    SCOPED_TRACE(k);
    const auto& c = expected[k];
    // On the surface to 1e-12, as `epviz section` promises.
    EXPECT_LE(std::abs(c.gamma.z()), sim::kSectionResidual);
    EXPECT_EQ(dots[k].x(), c.gamma.x());
    EXPECT_EQ(dots[k].y(), c.omega.z());
  }
  EXPECT_EQ(last.section->axes[0], "γ₁");
  EXPECT_EQ(last.section->axes[1], "Ω₃");
  // The range takes in every dot.
  const auto& r = last.section->range;
  for (const auto& p : dots) {
    EXPECT_TRUE(p.x() > r[0] && p.x() < r[1] && p.y() > r[2] && p.y() < r[3]);
  }
}

TEST(SectionPanel, ComparisonScenesShowEachRunsCrossingsInItsColour) {
  auto j = kovalevskaya_job(nlohmann::json::object());
  j["runs"] = {{{"label", "fine"}}, {{"label", "rk4"}, {"method", "rk4"}, {"step", 0.05}}};
  const auto job = render_job(j);
  const auto plan = job::plan_job(job);
  ASSERT_EQ(plan.others.size(), 1u);
  scene::FrameSource source(plan, job.scene);
  const auto f = source.frame(source.frame_count() - 1);
  ASSERT_TRUE(f.section && f.comparison);
  ASSERT_EQ(f.section->runs.size(), 2u);
  EXPECT_EQ(f.section->colours, f.comparison->colours);
  const auto rk4 = with_gamma2_sign(
      section_code_crossings(plan.others.front().run, job.scene.section->surface), 1);
  ASSERT_EQ(f.section->runs[1].size(), rk4.size());
  for (std::size_t k = 0; k < rk4.size(); ++k)
    EXPECT_EQ(f.section->runs[1][k].x(), rk4[k].gamma.x());
}

// The right-hand-side evaluations of `spec` integrated alone through its
// samples, as a render without a section panel integrates it.
long evals_alone(const sim::RunSpec& spec) {
  auto t = sim::Trajectory::start(spec);
  for (long k = 1; k <= spec.samples; ++k) t->next();
  return t->stats().rhs_evals + t->interpolation_evals();
}

TEST(SectionPanel, EachRunIsIntegratedOncePlusItsShadow) {
  // One run, and a comparison whose second run takes fixed steps.
  auto comparison = kovalevskaya_job(nlohmann::json::object());
  comparison["runs"] = {{{"label", "fine"}}, {{"label", "rk4"}, {"method", "rk4"}, {"step", 0.05}}};
  for (const auto& j : {kovalevskaya_job(nlohmann::json::object()), comparison}) {
    const auto job = render_job(j);
    const auto plan = job::plan_job(job);
    std::vector<sim::RunSpec> runs{plan.run};
    for (const auto& other : plan.others) runs.push_back(other.run);
    SCOPED_TRACE(runs.size());
    long alone = 0;  // every run and its shadow, each integrated once
    for (const auto& run : runs) alone += evals_alone(run) + evals_alone(scene::shadow_run(run));

    const long before = sim::rhs_evals_tallied();
    scene::FrameSource source(plan, job.scene);
    scene::Frame last;
    for (int i = 0; i < source.frame_count(); ++i) last = source.frame(i);
    const long spent = sim::rhs_evals_tallied() - before;
    ASSERT_TRUE(last.section);
    long crossings = 0;
    for (const auto& dots : last.section->runs) crossings += long(dots.size());
    crossings += long(last.section->hidden);  // found on the other sheet, as dear
    ASSERT_GT(crossings, 10);
    // A step that holds a crossing may need the dense output that no sample
    // in it asked for: DOP853's three more stages, or the two derivatives of
    // a fixed step's interpolant. Another pass over a run would cost
    // thousands.
    EXPECT_GE(spent, alone);
    EXPECT_LE(spent, alone + 3 * crossings) << "alone " << alone << ", spent " << spent;
  }
}

TEST(SectionPanel, CrossingsOfASpinorRunAreThoseOfAMuchTighterDirectSection) {
  // The space view integrates the spinor formulation: its crossings, found
  // on its own dense output, against `epviz section`'s direct formulation at
  // a hundredth of the tolerance.
  auto j = kovalevskaya_job(nlohmann::json::object());
  j["view"] = "space";
  j["simulation"]["tol"] = 1e-12;
  const auto job = render_job(j);
  const auto plan = job::plan_job(job);
  ASSERT_EQ(plan.run.formulation, sim::Formulation::spinor);
  scene::FrameSource source(plan, job.scene);
  scene::Frame last;
  for (int i = 0; i < source.frame_count(); ++i) last = source.frame(i);
  ASSERT_TRUE(last.section);
  sim::RunSpec tight = plan.run;
  tight.formulation = sim::Formulation::direct;
  tight.tol = plan.run.tol * 1e-2;
  const auto expected =
      with_gamma2_sign(section_code_crossings(tight, job.scene.section->surface), 1);
  const auto& dots = last.section->runs.front();
  ASSERT_GT(expected.size(), 10u);
  ASSERT_EQ(dots.size(), expected.size());
  double worst = 0;
  for (std::size_t k = 0; k < dots.size(); ++k) {
    SCOPED_TRACE(k);
    worst = std::max({worst, std::abs(dots[k].x() - expected[k].gamma.x()),
                      std::abs(dots[k].y() - expected[k].omega.z())});
    EXPECT_NEAR(dots[k].x(), expected[k].gamma.x(), 1e-7);
    EXPECT_NEAR(dots[k].y(), expected[k].omega.z(), 1e-7);
  }
  std::printf("worst %g n %zu\n", worst, dots.size());
}

TEST(SectionPanelKey, SheetDefaultsToThePositiveOneAndIsWrittenBack) {
  using scene::SectionSheet;
  // A chart with two sheets: the positive one unless asked.
  const auto d = job::read_job(kovalevskaya_job(nlohmann::json::object()), "job.json");
  EXPECT_EQ(d.scene.section->sheet, (SectionSheet{StateComponent::gamma2, 1}));
  EXPECT_EQ(job::write_job(d)["section"]["sheet"], "gamma2 > 0");
  // Asked: kept through a save and a read.
  const auto given = job::read_job(kovalevskaya_job({{"sheet", "gamma2 < 0"}}), "job.json");
  EXPECT_EQ(given.scene.section->sheet, (SectionSheet{StateComponent::gamma2, -1}));
  const auto saved = job::write_job(given);
  EXPECT_EQ(saved["section"]["sheet"], "gamma2 < 0");
  const auto back = job::read_job(nlohmann::json::parse(saved.dump()), "job.json");
  EXPECT_EQ(back.scene.section->sheet, given.scene.section->sheet);
  // Any component neither cut nor plotted, as in a section file.
  const auto omega = job::read_job(kovalevskaya_job({{"sheet", "omega1 > 0"}}), "job.json");
  EXPECT_EQ(omega.scene.section->sheet, (SectionSheet{StateComponent::omega1, 1}));
  // A chart with one sheet (a surface of omega3, plotted at two gammas): every crossing.
  const auto one = job::read_job(
      kovalevskaya_job({{"function", "omega3"}, {"coords", {"gamma1", "gamma2"}}}), "job.json");
  EXPECT_FALSE(one.scene.section->sheet);
  EXPECT_FALSE(job::write_job(one)["section"].contains("sheet"));
}

TEST(SectionPanel, TheNegativeSheetDrawsTheOthersAndCountsThese) {
  const auto job = render_job(kovalevskaya_job({{"sheet", "gamma2 < 0"}}));
  const auto plan = job::plan_job(job);
  scene::FrameSource source(plan, job.scene);
  const auto last = source.frame(source.frame_count() - 1);
  ASSERT_TRUE(last.section);
  const auto all = section_code_crossings(plan.run, job.scene.section->surface);
  const auto shown = with_gamma2_sign(all, -1);
  ASSERT_GT(shown.size(), 3u);
  const auto& dots = last.section->runs.front();
  ASSERT_EQ(dots.size(), shown.size());
  for (std::size_t k = 0; k < dots.size(); ++k) {
    EXPECT_LT(shown[k].gamma.y(), 0.0);
    EXPECT_EQ(dots[k].x(), shown[k].gamma.x());
    EXPECT_EQ(dots[k].y(), shown[k].omega.z());
  }
  EXPECT_EQ(last.section->hidden, all.size() - shown.size());
  EXPECT_EQ(last.section->title, "γ₃ = 0, upward, γ₂ < 0");
}

TEST(SectionPanel, ASectionRunThatLosesTheMotionIsANumericalFailure) {
  // RK4 at a coarse step drifts past the limit: exit 3 with the advice, as
  // when the drawn run loses it, not an error of another kind.
  TempDir dir;
  std::string job = R"({"simulation": {"case": "generic", "t_end": 200, "method": "rk4", )";
  job += R"("step": 0.3, "max_drift": 1e-3}, "section": {}, "width": 64, "height": 48, )";
  job += R"("fps": 2, "duration": 1, "output": {"dir": ")" + (dir / "out").string();
  job += R"(", "format": "png"}})";
  const auto file = dir.write("job.json", job);
  const auto r = test::run_epviz("render " + file.string() + " --quiet", dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("numerical failure"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace epviz
