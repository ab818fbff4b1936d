#include "live/live_session.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"
#include "io/json_text.hpp"
#include "io/png_writer.hpp"
#include "job/schema.hpp"
#include "live/camera_control.hpp"
#include "live/job_file.hpp"
#include "live/setup_limits.hpp"
#include "paint/section_panel_drawing.hpp"
#include "render/framebuffer.hpp"
#include "render/imgui_context_scope.hpp"
#include "sim/section_chart_inverse.hpp"

namespace epviz::live {
namespace {

constexpr double kFixedFrameSeconds = 1.0 / 30.0;
// A frame after a long pause must not jump the simulation ahead.
constexpr double kMaxFrameSeconds = 0.1;
constexpr int kSettleFrames = 3;

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

bool inside(const render::Viewport& v, float x, float y) {
  return x >= float(v.x) && y >= float(v.y) && x < float(v.x + v.width) &&
         y < float(v.y + v.height);
}

}  // namespace

LiveSession::LiveSession(render::GlContext& gl, SessionOptions options)
    : gl_(gl), options_(std::move(options)), scene_(options_.initial) {
  scene_.set_playing(options_.start_playing);
}

LiveSession::~LiveSession() = default;

void LiveSession::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  // Input not yet applied is in the old size's pixels (ImGui's own pointer is
  // in layout units, which a resize with the view's scale leaves alone).
  if (width_ > 0 && height_ > 0)
    gui_input_.rescale(float(width) / float(width_), float(height) / float(height_));
  width_ = width;
  height_ = height;
  if (!painter_) {
    paint::PainterOptions po;
    po.builtin_font = options_.builtin_font;
    painter_ = std::make_unique<paint::FramePainter>(gl_, width, height, po);
    render::GuiInput::configure(painter_->gui().context());
  } else {
    painter_->resize(width, height);
    // ImGui finds the window under the pointer from the last frame's layout:
    // lay the panels out at the new size before applying input given in it.
    hold_input_frames_ = std::max(hold_input_frames_, 1);
  }
  settle_frames_ = kSettleFrames;
}

void LiveSession::input(const render::InputEvent& event) { gui_input_.push(event); }

bool LiveSession::wants_frame() const {
  return painter_ && (settle_frames_ > 0 || gui_input_.pending() || scene_.playing() ||
                      save_frame_pending_ || scene_.section_filling());
}

double LiveSession::wall_seconds_since_last_frame() {
  if (options_.fixed_clock) return kFixedFrameSeconds;
  const auto now = std::chrono::steady_clock::now();
  const double dt =
      last_frame_ ? std::chrono::duration<double>(now - *last_frame_).count() : kFixedFrameSeconds;
  last_frame_ = now;
  return std::clamp(dt, 1e-4, kMaxFrameSeconds);
}

void LiveSession::observe(const render::InputEvent& e) {
  using Kind = render::InputEvent::Kind;
  settle_frames_ = kSettleFrames;
  const ImGuiIO& io = ImGui::GetIO();
  // Presses on the panels (or anywhere while a popup is open) are ImGui's.
  const bool gui_owns = panel_.contains(e.x, e.y) || io.WantCaptureMouse;
  switch (e.kind) {
    case Kind::mouse_button:
      if (e.button != 0) break;
      // The section panel by position: ImGui's wish to capture the mouse is
      // of the last frame's pointer, which may have been on the panels.
      if (e.down && !panel_.contains(e.x, e.y) &&
          !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel) &&
          click_section(e.x, e.y))
        break;
      if (e.down && !gui_owns && inside(view_3d_, e.x, e.y)) drag_.emplace(e.x, e.y);
      if (!e.down) drag_.reset();
      break;
    case Kind::mouse_move:
      if (drag_) {
        LiveSetup s = scene_.setup();
        s.scene.camera = orbit_by_drag(s.scene.camera, e.x - drag_->first, e.y - drag_->second,
                                       float(view_3d_.height));
        scene_.set_view(s.scene, s.speed);
        drag_.emplace(e.x, e.y);
      }
      break;
    case Kind::wheel:
      if (!gui_owns && inside(view_3d_, e.x, e.y)) {
        LiveSetup s = scene_.setup();
        s.scene.camera = zoom_by_wheel(s.scene.camera, e.wheel_y);
        scene_.set_view(s.scene, s.speed);
      }
      break;
    case Kind::key:
      // Shortcuts, unless the user is typing into a field.
      if (!e.down || io.WantTextInput || e.ctrl || e.alt || e.super) break;
      if (e.key == " ") scene_.set_playing(!scene_.playing());
      if (e.key == "r" || e.key == "R") scene_.restart();
      if (e.key == "s" || e.key == "S") scene_.step();
      break;
    case Kind::focus:
      if (!e.down) drag_.reset();
      break;
    case Kind::text: break;
  }
}

const render::RgbaImage& LiveSession::render() {
  if (!painter_) resize(1280, 720);
  if (save_frame_pending_)
    save_frame();  // before the picture with the panels: the painter reuses its image

  const double dt = wall_seconds_since_last_frame();
  render::ImGuiOverlay& gui = painter_->gui();
  gui.set_delta_time(float(dt));
  // The interface laid out as at full size and drawn at the view's scale,
  // so that a control lies where the page, which stretches the frame,
  // expects it at any scale.
  gui.set_framebuffer_scale(float(view_scale_));
  panel_.set_view_scale(float(view_scale_));
  if (hold_input_frames_ > 0)
    --hold_input_frames_;
  else
    gui_input_.apply(
        gui.context(), [this](const render::InputEvent& e) { observe(e); }, float(view_scale_));
  const auto simulate_start = Clock::now();
  scene_.update(dt);
  stages_.simulate_ms = ms_since(simulate_start);
  for (const std::string& note : scene_.take_section_notices()) notify(note, true);
  const scene::Frame& frame = scene_.frame();
  // The scene moves right of the expanded panel when the window is wide
  // enough to keep most of it; in a narrow window the panel floats over it.
  const int panel_px = panel_.occupied_width();
  const int reserved = panel_px > 0 && width_ - panel_px >= width_ / 2 ? panel_px : 0;
  painter_->set_reserved_left(reserved);
  // The frame's own layout: a comparison's legend strip and chart take room too.
  layout_ = paint::layout_for(frame, width_, height_, reserved);
  view_3d_ = layout_.view_3d ? paint::to_viewport(*layout_.view_3d)
                             : render::Viewport{reserved, 0, width_ - reserved, height_};

  PanelActions actions;
  const auto draw_start = Clock::now();
  const render::RgbaImage& image = painter_->paint(frame, [&] {
    // The panel is laid out in layout units (frame pixels / scale).
    actions = panel_.draw(scene_, render::Viewport{0, 0, int(std::lround(width_ / view_scale_)),
                                                   int(std::lround(height_ / view_scale_))});
    const bool popup_open =
        ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
    // Hidden in this frame (laid out), shown in the next, hoverable after it.
    if (popup_open && !popup_was_open_) hold_input_frames_ = 2;
    popup_was_open_ = popup_open;
  });
  stages_.read_back_ms = render::last_read_back_ms();
  stages_.draw_ms = std::max(0.0, ms_since(draw_start) - stages_.read_back_ms);
  if (panel_.occupied_width() != panel_px)
    settle_frames_ = kSettleFrames;  // lay the scene out again
  if (settle_frames_ > 0) --settle_frames_;
  apply(actions);
  return image;
}

bool LiveSession::click_section(float x, float y) {
  const auto& panel = scene_.frame().section;
  if (!panel || !layout_.section_area) return false;
  const auto at = paint::section_point_at(*panel, paint::to_viewport(*layout_.section_area), x, y);
  if (!at) return false;
  // The sheet drawn, which the panel's buttons set (and a served job's
  // section.sheet, the buttons unseen while their part is closed).
  const auto& drawn = scene_.section()->settings();
  const auto chart = sim::chart_sheet_component(drawn.surface, drawn.coords);
  const int sheet = drawn.sheet && chart && drawn.sheet->component == *chart ? drawn.sheet->sign
                                                                             : panel_.click_sheet();
  const LiveSection::Added added = scene_.add_section_orbit(at->x, at->y, sheet);
  notify(added.notice, !added.added);
  return true;
}

void LiveSession::notify(const std::string& note, bool error) {
  panel_.set_message(note, error);
  notices_.push_back(note);
}

void LiveSession::apply(const PanelActions& a) {
  const bool any = a.toggle_play || a.step || a.restart || a.load_case || a.rerun || a.view ||
                   a.save_frame || a.save_job || a.clear_orbits;
  if (!any) return;
  settle_frames_ = kSettleFrames;
  if (a.toggle_play) scene_.set_playing(!scene_.playing());
  if (a.step) scene_.step();
  if (a.restart) scene_.restart();
  if (a.view) {
    if (auto why = out_of_range(*a.view, scene_.setup()))
      panel_.set_message("not applied: " + *why, true);
    else
      scene_.set_view(a.view->scene, a.view->speed);
  }
  if (a.rerun) rerun(*a.rerun);
  if (a.load_case) {
    LiveSetup s = options_.presets(*a.load_case);
    s.scene.layers = scene_.setup().scene.layers;  // the user's layers stay as chosen
    if (!s.scene.section) s.scene.section = scene_.setup().scene.section;  // and the section
    // The runs compared that are relative to the first stay; those a served
    // job gave in full belong to its body and state.
    for (const auto& c : scene_.setup().compared)
      if (!c.given) s.compared.push_back(c);
    rerun(s);
  }
  if (a.clear_orbits) scene_.clear_section_orbits();
  if (a.save_frame) save_frame_pending_ = true;
  if (a.save_job) save_job();
}

// Whether two runs start from one body and state (so on one level).
static bool same_start(const sim::RunSpec& a, const sim::RunSpec& b) {
  return a.body.inertia == b.body.inertia && a.body.com == b.body.com &&
         a.body.weight == b.body.weight && a.initial.omega == b.initial.omega &&
         a.initial.gamma == b.initial.gamma;
}

void LiveSession::rerun(const LiveSetup& given) {
  const bool was_playing = scene_.playing();
  LiveSetup s = given;
  // Clicked orbits lie on the first run's level: another body or start leaves them.
  bool orbits_left = false;
  if (s.scene.section && !s.scene.section->orbits.empty() &&
      !same_start(s.run, scene_.setup().run)) {
    s.scene.section->orbits.clear();
    orbits_left = true;
  }
  // Every value the page could have typed, against its range, before any work.
  if (auto why = out_of_range(s, scene_.setup())) {
    panel_.set_message("not applied: " + *why, true);
    return;
  }
  try {
    physics::validate_body(s.run.body, false);
    (void)physics::validate_initial_state(s.run.initial, false);
    scene_.restart(s);
    scene_.set_playing(was_playing);
    panel_.set_message(orbits_left ? "the section's orbits were cleared: they lay on the old level"
                                   : "");
  } catch (const std::exception& e) {
    // The running scene is kept; the panel says why the edit was refused.
    panel_.set_message(std::string("not applied: ") + e.what(), true);
  }
}

void LiveSession::deliver(serve::Download d) {
  std::string note = "sent " + d.name + " to the browser";
  bool failed = false;
  if (!options_.save_dir.empty()) {
    const auto path = options_.save_dir / d.name;
    try {
      std::filesystem::create_directories(options_.save_dir);
      io::write_file_atomically(
          path, std::span(reinterpret_cast<const std::byte*>(d.bytes.data()), d.bytes.size()));
      note = "saved " + path.string();
    } catch (const std::exception& e) {
      note = std::string("could not save: ") + e.what();
      failed = true;
    }
  }
  panel_.set_message(note, failed);
  notices_.push_back(note);
  downloads_.push_back(std::move(d));
}

void LiveSession::save_frame() {
  save_frame_pending_ = false;
  // The picture without the panels, as `epviz render` would draw it.
  const render::RgbaImage& clean = painter_->paint(scene_.frame());
  char name[160];
  std::snprintf(name, sizeof name, "%s_t%08.3f.png", panel_.save_name().c_str(), scene_.time());
  deliver({name, "image/png", io::encode_png_rgba(clean.width, clean.height, clean.pixels)});
}

void LiveSession::save_job() {
  // The picture as seen: this view's size (the scene's part of it is what a render draws).
  LiveSetup setup = scene_.setup();
  // The page's size: the server may be rendering it smaller just now (adaptive resolution).
  setup.scene.width = int(std::lround(width_ / view_scale_));
  setup.scene.height = int(std::lround(height_ / view_scale_));
  // The tolerance the run was planned with: a zoom since then changes what
  // live_tolerance would choose for the setup, not what was run.
  std::optional<double> tolerance;
  if (live_tolerance(scene_.setup())) tolerance = scene_.tolerance();
  const LiveMoment moment{scene_.time(), tolerance};
  const job::JobDocument job = job_document(setup, panel_.save_name(), moment);
  const std::string text = io::json_text(job::write_job(job), 2) + "\n";
  const std::string file_name = panel_.save_name() + ".json";
  // Only a job that `epviz render` accepts leaves: a setup it would refuse
  // (a step too small for the time watched, say) is said in the panel.
  try {
    check_render_accepts(text, file_name);
  } catch (const std::exception& e) {
    const std::string note = std::string("not saved: ") + e.what();
    panel_.set_message(note, true);
    notices_.push_back(note);
    return;
  }
  deliver({file_name, "application/json", std::vector<std::uint8_t>(text.begin(), text.end())});
  // Render jobs have no start time; the live run started at t = 0 too.
  if (moment.time > 0) {
    char note[200];
    std::snprintf(note, sizeof note,
                  "the job runs from t = 0, where this run started, to t = %.3f, the moment "
                  "shown: %.1f s of video at the live speed",
                  moment.time, job.scene.duration);
    notices_.push_back(note);
  }
}

std::vector<serve::Download> LiveSession::take_downloads() { return std::exchange(downloads_, {}); }
std::vector<std::string> LiveSession::take_notices() { return std::exchange(notices_, {}); }

std::string LiveSession::controls_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, r] : panel_.controls()) j[name] = {r[0], r[1], r[2], r[3]};
  j["view3d"] = {view_3d_.x, view_3d_.y, view_3d_.width, view_3d_.height};
  // The section panel's plot (clicks there start orbits) and how many
  // crossings each of its runs and orbits shows, and how many lie on the
  // sheet not drawn (counted, not shown): an object, not a rectangle.
  if (const auto& a = layout_.section_area; a && scene_.frame().section) {
    nlohmann::json dots = nlohmann::json::array();
    for (const auto& run : scene_.frame().section->runs) dots.push_back(run.size());
    j["section"] = {{"plot", {a->x, a->y, a->width, a->height}},
                    {"dots", std::move(dots)},
                    {"hidden", scene_.frame().section->hidden}};
  }
  return io::json_text(j);
}

}  // namespace epviz::live
