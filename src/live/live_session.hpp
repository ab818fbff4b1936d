#pragma once
// One browser tab's interactive scene: the simulation (LiveScene), the ImGui
// panels that edit it, the orbit camera, and the painter that draws it all.
// Each connection gets its own session, so every tab has its own window size,
// panels and run, as a desktop window would (docs/serve.md says why).
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "live/control_panel.hpp"
#include "live/live_scene.hpp"
#include "paint/frame_painter.hpp"
#include "render/gl_context.hpp"
#include "render/gui_input.hpp"
#include "serve/session.hpp"

namespace epviz::live {

struct SessionOptions {
  LiveSetup initial = preset_setup(physics::Case::kovalevskaya);
  // The setup the case combo loads for a case (the app reads render_jobs/<case>.json).
  std::function<LiveSetup(physics::Case)> presets = preset_setup;
  // Saved frames and jobs are also written here (atomically); empty: only sent to the browser.
  std::filesystem::path save_dir;
  // Replays: every frame is 1/30 s of wall-clock time, so a recorded event
  // stream gives the same frames on any machine.
  bool fixed_clock = false;
  bool builtin_font = false;  // ImGui's bitmap font (tests)
  bool start_playing = false;
};

class LiveSession : public serve::Session {
 public:
  // `gl` must be current on this thread and outlive the session.
  LiveSession(render::GlContext& gl, SessionOptions options);
  ~LiveSession() override;

  void resize(int width, int height) override;
  void set_view_scale(double scale) override { view_scale_ = scale; }
  void input(const render::InputEvent& event) override;
  bool wants_frame() const override;
  const render::RgbaImage& render() override;
  std::vector<serve::Download> take_downloads() override;
  std::vector<std::string> take_notices() override;
  std::string controls_json() const override;
  serve::RenderStages last_render_stages() const override { return stages_; }

  const LiveScene& scene() const { return scene_; }
  const ControlPanel& panel() const { return panel_; }
  const render::Viewport& view_3d() const { return view_3d_; }
  // The last frame's layout and what the painter placed over it (legend rows, labels).
  const scene::FrameLayout& layout() const { return layout_; }
  const paint::PaintedAnnotations& annotations() const { return painter_->annotations(); }
  bool dragging() const { return drag_.has_value(); }

 private:
  void observe(
      const render::InputEvent& e);  // the scene's own use of input: orbit, zoom, shortcuts
  void apply(const PanelActions& a);
  // A press at (x, y): on the section panel's plot it starts an orbit from
  // that point (or says why none); returns whether it was there.
  bool click_section(float x, float y);
  void notify(const std::string& note, bool error);
  void rerun(const LiveSetup& s);
  void save_frame();
  void save_job();
  void deliver(serve::Download d);
  double wall_seconds_since_last_frame();

  render::GlContext& gl_;
  SessionOptions options_;
  LiveScene scene_;
  ControlPanel panel_;
  render::GuiInput gui_input_;
  std::unique_ptr<paint::FramePainter> painter_;
  int width_ = 0, height_ = 0;
  render::Viewport view_3d_;
  scene::FrameLayout layout_;
  std::optional<std::pair<float, float>> drag_;  // last pointer position of an orbit drag
  int settle_frames_ = 1;  // frames still to draw after a change (ImGui needs one or two to settle)
  // Frames still drawn without applying input, after a popup (a combo's
  // list) opened: ImGui lays a new popup out unseen in its first frame and
  // hovers only what the previous frame showed, so a pick that arrived with
  // the click that opened the list would land on nothing and close it.
  int hold_input_frames_ = 0;
  bool popup_was_open_ = false;
  bool save_frame_pending_ = false;
  std::vector<serve::Download> downloads_;
  std::vector<std::string> notices_;
  std::optional<std::chrono::steady_clock::time_point> last_frame_;
  serve::RenderStages stages_;  // of the last render()
  // The server's scale of this view (set_view_scale): the panels and labels
  // are laid out as at full size and drawn at this scale, so they keep their
  // size and place on the page, which stretches the frame.
  double view_scale_ = 1.0;
};

}  // namespace epviz::live
