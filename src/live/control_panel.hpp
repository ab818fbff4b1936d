#pragma once
// The ImGui panels of the interactive scene. The panel edits a copy of the
// running setup and reports what the user asked for; the session applies it
// (a new run, a view change, saving), so the panel owns no simulation state.
#include <array>
#include <map>
#include <optional>
#include <string>

#include "live/live_scene.hpp"
#include "render/camera.hpp"

namespace epviz::live {

struct PanelActions {
  bool toggle_play = false;
  bool step = false;
  bool restart = false;
  std::optional<physics::Case> load_case;  // the case combo: that preset's setup
  std::optional<LiveSetup> rerun;          // edits that need a new run from t = 0
  std::optional<LiveSetup> view;           // edits of layers, camera, speed, trail: no new run
  bool save_frame = false;
  bool save_job = false;
  bool clear_orbits = false;  // the section panel's clicked orbits
};

using Rect = std::array<float, 4>;  // x, y, width, height in frame pixels

class ControlPanel {
 public:
  // Draws the panels in the top-left corner of `area` (the 3D view) for the
  // scene's current state. Call inside an ImGui frame.
  PanelActions draw(const LiveScene& scene, const render::Viewport& area);

  // A line shown under the playback buttons (saved file, refused edit, ...).
  void set_message(std::string text, bool error = false);
  const std::string& message() const { return message_; }
  bool message_is_error() const { return message_is_error_; }
  // Where the named controls were in the last frame: "play", "step",
  // "restart", "speed", "case", "case:<name>" (items of the open combo),
  // "stay", "broken" (a broken condition's line), "behind" (the run cannot
  // keep up with its speed), "I1", "I2", "I3", "com", "weight", "omega",
  // "gamma", "formulation", "formulation:<name>", "method", "method:<name>",
  // "auto_tol", "run_tol" / "run_step" (the first run's), "trail", "list:case" / "list:formulation" /
  // "list:method" (an open combo's list), "header:<section>", "file_name",
  // "save_frame", "save_job", the runs section's "run:<n>" (legend rows),
  // "remove:<n>" (n = 2, 3, ...), "new_method", "new_method:<name>",
  // "list:new_method", "new_step" / "new_tol", "add_run", "nudge", "add_nudged",
  // the section's "header:section", "section" (the panel shown), "sheet:+" /
  // "sheet:-" (the sheet a click starts on), "clear_orbits",
  // and "panel" (the whole window).
  const std::map<std::string, Rect>& controls() const { return controls_; }
  // Whether (x, y) is on the panel (a press there is the panel's, not an orbit).
  bool contains(float x, float y) const;
  // The pixels the expanded panel takes from the left edge (0 when collapsed
  // or not drawn yet), so the scene can be laid out beside it.
  int occupied_width() const { return collapsed_ ? 0 : occupied_width_; }
  // The overlay's framebuffer scale: the panel is laid out in units of
  // frame pixels / scale, and controls() are given in frame pixels.
  void set_view_scale(float scale) { view_scale_ = scale; }
  // The formulation the formulation box showed last (the one the scene integrates).
  sim::Formulation shown_formulation() const { return shown_formulation_; }
  // The file name stem for saved frames and jobs (editable in the panel).
  const std::string& save_name() const { return save_name_; }
  // The sheet a click on the section panel starts an orbit on: +1 or -1, the
  // sign of the component the chart leaves out (gamma2 for gamma3 = 0 at (gamma1, Omega3)).
  int click_sheet() const { return click_sheet_; }

 private:
  void note_item(const char* name);    // records the last item's rectangle
  void note_window(const char* name);  // records the current window's (a combo's list)
  void draw_playback(const LiveScene& scene, PanelActions& out);
  void draw_case_and_body(const LiveScene& scene, PanelActions& out);
  void draw_integrator(const LiveScene& scene, PanelActions& out);
  void draw_view(const LiveScene& scene, PanelActions& out);
  void draw_drift(const LiveScene& scene);
  void draw_runs(const LiveScene& scene, PanelActions& out);
  void draw_section(const LiveScene& scene, PanelActions& out);
  void draw_save();

  std::map<std::string, Rect> controls_;
  std::string message_;
  bool message_is_error_ = false;
  bool collapsed_ = false;
  int occupied_width_ = 0;
  float view_scale_ = 1.0f;
  std::string save_name_ = "epviz_live";
  sim::Formulation shown_formulation_ = sim::Formulation::direct;
  physics::Case left_case_ = physics::Case::custom;  // the last named case shown
  // The next run to compare, as chosen in the runs section (the method: the first run's when unset).
  std::optional<sim::Method> new_method_;
  double new_step_ = 0.25, new_tol_ = 1e-8;  // a coarse step, as compare_methods.json shows RK4
  double nudge_ = 1e-6;
  int click_sheet_ = 1;
  // The section last shown (a loaded job's own surface and axes), shown again when switched on.
  std::optional<scene::SectionPanelSettings> last_section_;
};

}  // namespace epviz::live
