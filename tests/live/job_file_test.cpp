// A setup saved from the interactive scene is a render job that `epviz
// render` accepts and that reproduces the edited body.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "job/schema.hpp"
#include "live/job_file.hpp"
#include "scene/theme.hpp"
#include "support/cli.hpp"

namespace epviz::live {
namespace {

TEST(JobFile, EpvizRenderAcceptsTheSavedSetupOfEveryCase) {
  test::TempDir dir;
  for (const auto& p : physics::case_presets()) {
    LiveSetup s = preset_setup(p.id);
    s.run.body.weight = 1.75;  // an edit the job must carry
    s.scene.camera.azimuth_deg = 80.0;
    const auto file = dir / (p.name + ".json");
    std::ofstream(file) << render_job_json(s, p.name, {}, 2.0);
    const auto r = test::run_epviz("render " + file.string() +
                                       " --frames 0 --format png --width 160 --height 90 "
                                       "--quiet --out " +
                                       (dir / p.name).string(),
                                   dir);
    EXPECT_EQ(r.exit_code, 0) << p.name << ": " << r.err;
    bool png_written = false;
    if (std::filesystem::is_directory(dir / p.name))
      for (const auto& f : std::filesystem::directory_iterator(dir / p.name))
        png_written |= f.path().extension() == ".png";
    EXPECT_TRUE(png_written) << p.name;
    const auto j = nlohmann::json::parse(test::slurp(file));
    EXPECT_EQ(j["simulation"]["weight"], 1.75);
    EXPECT_EQ(j["simulation"]["case"], p.name);
    EXPECT_EQ(j["camera"]["azimuth"], 80.0);
  }
}

TEST(JobFile, ABodyOutsideItsCaseIsSavedAsACustomBody) {
  LiveSetup s = preset_setup(physics::Case::kovalevskaya);
  s.run.case_id = physics::Case::custom;
  s.run.body.inertia.z() = 1.3;
  const auto j = nlohmann::json::parse(render_job_json(s, "edited"));
  EXPECT_FALSE(j["simulation"].contains("case"));
  EXPECT_EQ(j["simulation"]["inertia"][2], 1.3);
}

template <class T>
void expect_same(const job::Given<T>& written, const job::Given<T>& read, const char* key) {
  EXPECT_EQ(bool(written), bool(read)) << key;
  if (written && read) {
    EXPECT_EQ(*written, *read) << key;
  }
}

// Setups that between them use every key the writer can write.
std::vector<LiveSetup> varied_setups() {
  std::vector<LiveSetup> setups{
      preset_setup(physics::Case::lagrange)};  // adaptive, tolerance "auto"
  LiveSetup a = preset_setup(physics::Case::kovalevskaya);
  a.scene.auto_tolerance = false;
  a.run.tol = 3e-9;
  a.run.formulation = sim::Formulation::spinor;
  a.scene.title = "Edited top";
  a.scene.theme = scene::ThemeId::light;
  a.scene.colours = scene::light_theme().colours;
  a.scene.colours.marker = {0.2f, 0.4f, 0.6f, 0.5f};
  a.scene.view = scene::View::space;
  a.scene.camera = {12.5, -30.25, 5.5};
  a.scene.layers.riccati = false;
  a.scene.plane_extent = 3.25f;
  a.scene.width = 640;
  a.scene.height = 480;
  setups.push_back(a);
  LiveSetup b = preset_setup(
      physics::Case::generic);  // a fixed step, the Riccati chart switch, a custom body
  b.run.case_id = physics::Case::custom;
  b.run.method = sim::Method::rk4;
  b.run.step = 0.0125;
  b.run.formulation = sim::Formulation::riccati;
  b.run.chart_switch = true;
  b.scene.layers.overlay = false;
  setups.push_back(b);
  return setups;
}

TEST(JobFile, EveryWrittenFieldIsReadBackEqual) {
  for (const auto& setup : varied_setups()) {
    const job::JobDocument w = job_document(setup, "round", {}, 3.0);
    const std::string text = render_job_json(setup, "round", {}, 3.0);
    const job::JobDocument r = job::read_job(nlohmann::json::parse(text), "round.json");
    SCOPED_TRACE(text);
    const auto &ws = w.simulation, &rs = r.simulation;
    expect_same(ws.case_name, rs.case_name, "case");
    expect_same(ws.inertia, rs.inertia, "inertia");
    expect_same(ws.com, rs.com, "com");
    expect_same(ws.omega, rs.omega, "omega");
    expect_same(ws.gamma, rs.gamma, "gamma");
    expect_same(ws.weight, rs.weight, "weight");
    expect_same(ws.tol, rs.tol, "tol");
    expect_same(ws.step, rs.step, "step");
    expect_same(ws.t_end, rs.t_end, "t_end");
    expect_same(ws.samples, rs.samples, "samples");
    expect_same(ws.formulation, rs.formulation, "formulation");
    expect_same(ws.method, rs.method, "method");
    expect_same(ws.allow_nonphysical, rs.allow_nonphysical, "allow_nonphysical");
    expect_same(ws.normalize_gamma, rs.normalize_gamma, "normalize_gamma");
    expect_same(ws.chart_switch, rs.chart_switch, "chart_switch");

    const auto &wc = w.scene, &rc = r.scene;
    EXPECT_EQ(wc.auto_tolerance, rc.auto_tolerance);
    EXPECT_EQ(wc.title, rc.title);
    EXPECT_EQ(wc.view, rc.view);
    EXPECT_EQ(wc.theme, rc.theme);
    EXPECT_EQ(wc.camera.azimuth_deg, rc.camera.azimuth_deg);
    EXPECT_EQ(wc.camera.elevation_deg, rc.camera.elevation_deg);
    EXPECT_EQ(wc.camera.distance, rc.camera.distance);
    EXPECT_EQ(wc.layers.body, rc.layers.body);
    EXPECT_EQ(wc.layers.sphere, rc.layers.sphere);
    EXPECT_EQ(wc.layers.riccati, rc.layers.riccati);
    EXPECT_EQ(wc.layers.overlay, rc.layers.overlay);
    // Colours are written with 8 bits a channel: the same bytes come back.
    for (auto m : {&scene::Colours::background, &scene::Colours::body, &scene::Colours::sphere,
                   &scene::Colours::marker})
      EXPECT_EQ(job::hex_colour(wc.colours.*m), job::hex_colour(rc.colours.*m));
    EXPECT_EQ(wc.trail_length, rc.trail_length);
    EXPECT_EQ(wc.plane_extent, rc.plane_extent);
    EXPECT_EQ(wc.width, rc.width);
    EXPECT_EQ(wc.height, rc.height);
    EXPECT_EQ(wc.fps, rc.fps);
    EXPECT_EQ(wc.duration, rc.duration);
    EXPECT_EQ(w.output.dir, r.output.dir);
    EXPECT_EQ(w.output.video, r.output.video);
    EXPECT_EQ(w.output.name, r.output.name);

    // And what is read writes the same file again, whatever keys the format gains.
    EXPECT_EQ(job::write_job(r).dump(2) + "\n", text);
  }
}

// The job format bounds some numbers (job/schema.hpp); whatever the live
// controls reach must stay inside them, or a saved job would not render.
TEST(JobFile, TheLiveControlsLimitsAreInsideTheJobFormatsBounds) {
  for (const double distance : {1.5, 20.0}) {  // the orbit camera's zoom range
    LiveSetup s = preset_setup(physics::Case::lagrange);
    s.scene.camera.distance = distance;
    const auto text = render_job_json(s, "edge", {}, 2.0);
    EXPECT_NO_THROW(job::read_job(nlohmann::json::parse(text), "edge.json")) << text;
  }
  EXPECT_GT(1.5, job::min_camera_distance);
  EXPECT_LE(20.0, job::max_camera_distance);
  const scene::SceneSettings defaults;
  EXPECT_GE(defaults.plane_extent, job::min_plane_extent);
  EXPECT_LE(defaults.plane_extent, job::max_plane_extent);
}

void expect_listed(const nlohmann::json& object, const std::string& prefix,
                   const std::vector<std::string>& listed) {
  for (const auto& [key, value] : object.items()) {
    const std::string path = prefix + key;
    EXPECT_NE(std::find(listed.begin(), listed.end(), path), listed.end()) << path;
    if (value.is_object()) expect_listed(value, path + ".", listed);
  }
}

TEST(JobFile, EveryWrittenKeyIsInTheFormatsTable) {
  std::vector<std::string> listed;
  for (const auto& k : job::render_job_keys()) {
    EXPECT_FALSE(k.help.empty()) << k.path;
    listed.push_back(k.path);
  }
  for (const auto& setup : varied_setups())
    expect_listed(nlohmann::json::parse(render_job_json(setup, "keys")), "", listed);
}

}  // namespace
}  // namespace epviz::live
