#include "live/control_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "live/case_constraints.hpp"
#include "live/setup_limits.hpp"
#include "physics/cases.hpp"
#include "physics/notation.hpp"
#include "render/font_text.hpp"
#include "scene/frame_source.hpp"
#include "scene/run_palette.hpp"
#include "scene/theme.hpp"
#include "sim/section_chart_inverse.hpp"

namespace epviz::live {
namespace {

// The interactive panels are ImGui's dark windows: the dark theme's colours.
const scene::Theme& kTheme = scene::dark_theme();
ImVec4 to_imgui(const scene::Rgba& c) { return {c[0], c[1], c[2], c[3]}; }
const ImVec4 kErrorColour = to_imgui(kTheme.drift_bad);
const ImVec4 kGoodColour = to_imgui(kTheme.drift_ok);
const ImVec4 kWarnColour = to_imgui(kTheme.drift_warn);

bool drag_double(const char* label, double* v, double speed, double lo, double hi,
                 const char* format = "%.4g") {
  return ImGui::DragScalar(label, ImGuiDataType_Double, v, float(speed), &lo, &hi, format);
}

bool log_slider(const char* label, double* v, double lo, double hi, const char* format) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, v, &lo, &hi, format,
                             ImGuiSliderFlags_Logarithmic);
}

// A new run of `setup` in which the edited body keeps its case when it can:
// with "stay in case" the conditions are enforced; without it, a body that
// breaks them runs as a custom body (its fourth integral is not conserved).
LiveSetup edited_body(LiveSetup s, physics::Case chosen, Edited what) {
  if (s.stay_in_case) {
    enforce_case(chosen, what, s.run.body, s.run.initial);
    s.run.case_id = chosen;
  } else {
    s.run.case_id = physics::broken_condition(chosen, s.run.body, s.run.initial)
                        ? physics::Case::custom
                        : chosen;
  }
  // A job's title describes its case ("Kovalevskaya top"); a body that left
  // the case is titled by what it is now.
  if (s.run.case_id != chosen) s.scene.title.clear();
  return s;
}

struct PlotData {
  const std::deque<DriftPoint>* history;
  int which;  // 0 |γ|², 1 C₀, 2 C₁, 3 the fourth integral
};

float drift_log10(void* data, int index) {
  const auto* d = static_cast<const PlotData*>(data);
  const sim::Drifts& x = (*d->history)[std::size_t(index)].drift;
  const double v = d->which == 0   ? x.gamma_norm2
                   : d->which == 1 ? x.area
                   : d->which == 2 ? x.energy
                                   : x.extra.value_or(0.0);
  // Round-off level at the bottom; a non-finite drift pins the top.
  if (!std::isfinite(v)) return 0.0f;
  return float(std::log10(std::max(std::abs(v), 1e-17)));
}

}  // namespace

void ControlPanel::set_message(std::string text, bool error) {
  message_ = std::move(text);
  message_is_error_ = error;
}

void ControlPanel::note_item(const char* name) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  const float s = view_scale_;  // layout units to frame pixels
  controls_[name] = {a.x * s, a.y * s, (b.x - a.x) * s, (b.y - a.y) * s};
}

void ControlPanel::note_window(const char* name) {
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  const float s = view_scale_;
  controls_[name] = {pos.x * s, pos.y * s, size.x * s, size.y * s};
}

bool ControlPanel::contains(float x, float y) const {
  const auto it = controls_.find("panel");
  if (it == controls_.end()) return false;
  const Rect& r = it->second;
  return x >= r[0] && y >= r[1] && x < r[0] + r[2] && y < r[1] + r[3];
}

PanelActions ControlPanel::draw(const LiveScene& scene, const render::Viewport& area) {
  PanelActions out;
  controls_.clear();
  const float font = ImGui::GetFontSize();
  const float width = std::min(24.0f * font, float(area.width) - 16.0f);
  ImGui::SetNextWindowPos(ImVec2(float(area.x) + 8.0f, float(area.y) + 8.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f),
                                      ImVec2(width, std::max(80.0f, float(area.height) - 16.0f)));
  ImGui::SetNextWindowBgAlpha(0.82f);
  // The panel may let the scene show through; a combo's list over the panel
  // must not, or the panel's text reads through the list's items.
  ImVec4 popup_bg = ImGui::GetStyle().Colors[ImGuiCol_PopupBg];
  popup_bg.w = 1.0f;
  ImGui::PushStyleColor(ImGuiCol_PopupBg, popup_bg);
  // As tall as its contents up to the view's height, scrolling beyond it
  // (an always-auto-resizing window would cut off what does not fit).
  ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
  const bool open =
      ImGui::Begin("epviz", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  if (open) {
    ImGui::PushItemWidth(-9.0f * font);  // room for the labels on the right
    draw_playback(scene, out);
    auto header = [&](const char* title, const char* name, bool open_at_start) {
      const bool shown =
          ImGui::CollapsingHeader(title, open_at_start ? ImGuiTreeNodeFlags_DefaultOpen : 0);
      note_item(name);
      return shown;
    };
    if (header("Case and body", "header:case", true)) draw_case_and_body(scene, out);
    if (header("Integrator", "header:integrator", false)) draw_integrator(scene, out);
    if (header("Compare runs", "header:runs", false)) draw_runs(scene, out);
    if (header("View", "header:view", false)) draw_view(scene, out);
    static const std::string section_title = render::drawable_text("Poincaré section");
    if (header(section_title.c_str(), "header:section", bool(scene.section())))
      draw_section(scene, out);
    if (header("Invariant drift", "header:drift", true)) draw_drift(scene);
    ImGui::PopItemWidth();
  }
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  controls_["panel"] = {pos.x * view_scale_, pos.y * view_scale_, size.x * view_scale_,
                        size.y * view_scale_};  // frame pixels
  collapsed_ = !open;
  occupied_width_ = int(std::ceil((pos.x + size.x + 8.0f) * view_scale_));  // frame pixels
  ImGui::End();
  ImGui::PopStyleColor();
  return out;
}

void ControlPanel::draw_playback(const LiveScene& scene, PanelActions& out) {
  const LiveSetup& s = scene.setup();
  ImGui::TextColored(to_imgui(kTheme.title), "%s",
                     render::drawable_text(s.scene.title.empty() ? scene::case_title(s.run.case_id)
                                                                 : s.scene.title)
                         .c_str());
  ImGui::Text("t = %.3f   %s, %s", scene.time(), std::string(sim::name(s.run.method)).c_str(),
              scene.accuracy_note().c_str());
  const float button_w = 5.5f * ImGui::GetFontSize();
  if (ImGui::Button(scene.playing() ? "Pause" : "Play", ImVec2(button_w, 0)))
    out.toggle_play = true;
  note_item("play");
  ImGui::SameLine();
  if (ImGui::Button("Step", ImVec2(button_w, 0))) out.step = true;
  note_item("step");
  ImGui::SameLine();
  if (ImGui::Button("Restart", ImVec2(button_w, 0))) out.restart = true;
  note_item("restart");
  double speed = s.speed;
  if (log_slider("speed (t/s)", &speed, kMinSpeed, kMaxSpeed, "%.3g")) {
    LiveSetup v = s;
    v.speed = speed;
    out.view = v;
  }
  note_item("speed");
  if (ImGui::Button("Save PNG", ImVec2(button_w, 0))) out.save_frame = true;
  note_item("save_frame");
  ImGui::SameLine();
  if (ImGui::Button("Save job", ImVec2(button_w, 0))) out.save_job = true;
  note_item("save_job");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("a render job file that `epviz render` accepts");
  // The name on the same row: a section of its own ended up below the fold.
  ImGui::SameLine();
  ImGui::SetNextItemWidth(std::max(2.0f * button_w / 5.5f, ImGui::GetContentRegionAvail().x));
  draw_save();
  ImGui::TextDisabled("Space: play/pause   R: restart   S: step");
  if (!scene.keeping_up() && !scene.failure()) {
    // The frame's step budget holds the run back (live_scene.hpp): said,
    // so that a slow picture is not taken for the motion's own pace.
    ImGui::PushStyleColor(ImGuiCol_Text, kWarnColour);
    ImGui::TextWrapped(
        "behind: plays at %.0f%% of the speed (its steps cost more than a frame may spend; "
        "a larger step or tolerance, or a lower speed, keeps up)",
        100.0 * scene.pace());
    ImGui::PopStyleColor();
    note_item("behind");
  }
  if (scene.failure()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
    ImGui::TextWrapped("Stopped: %s", scene.failure()->c_str());
    ImGui::PopStyleColor();
  }
  if (!message_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, message_is_error_ ? kErrorColour : kGoodColour);
    ImGui::TextWrapped("%s", message_.c_str());
    ImGui::PopStyleColor();
  }
}

void ControlPanel::draw_case_and_body(const LiveScene& scene, PanelActions& out) {
  const LiveSetup& s = scene.setup();
  const physics::Case current = s.run.case_id;
  const std::string preview =
      current == physics::Case::custom ? "custom body" : physics::case_name(current);
  if (ImGui::BeginCombo("case", preview.c_str())) {
    note_window("list:case");
    for (const auto& p : physics::case_presets()) {
      if (ImGui::Selectable(p.name.c_str(), p.id == current)) out.load_case = p.id;
      note_item(("case:" + p.name).c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p.summary.c_str());
    }
    ImGui::EndCombo();
  }
  note_item("case");
  bool stay = s.stay_in_case;
  if (current == physics::Case::custom) ImGui::BeginDisabled();
  if (ImGui::Checkbox("stay in case", &stay)) {
    LiveSetup v = s;
    v.stay_in_case = stay;
    out.rerun = v;
  }
  note_item("stay");
  if (current == physics::Case::custom) ImGui::EndDisabled();
  if (current != physics::Case::custom && current != physics::Case::generic)
    ImGui::TextWrapped("conditions: %s", case_conditions_summary(current));
  if (current != physics::Case::custom) left_case_ = current;
  // A custom body that came from a case says which of its conditions it broke.
  const physics::Case judged = current == physics::Case::custom ? left_case_ : current;
  if (auto broken = physics::broken_condition(judged, s.run.body, s.run.initial)) {
    ImGui::PushStyleColor(ImGuiCol_Text, kWarnColour);
    if (judged != current)
      ImGui::TextWrapped("not the %s case: %s", physics::case_name(judged).c_str(),
                         broken->c_str());
    else
      ImGui::TextWrapped("%s", broken->c_str());
    ImGui::PopStyleColor();
    note_item("broken");
  }

  LiveSetup e = s;
  auto edited = [&](Edited what) { out.rerun = edited_body(e, current, what); };
  double* I = e.run.body.inertia.data();
  if (drag_double("I1", &I[0], 0.01, 0.01, 100.0)) edited(Edited::inertia_1);
  note_item("I1");
  if (drag_double("I2", &I[1], 0.01, 0.01, 100.0)) edited(Edited::inertia_2);
  note_item("I2");
  if (drag_double("I3", &I[2], 0.01, 0.01, 100.0)) edited(Edited::inertia_3);
  note_item("I3");
  if (ImGui::DragScalarN("centre of mass", ImGuiDataType_Double, e.run.body.com.data(), 3, 0.01f,
                         nullptr, nullptr, "%.4g"))
    edited(Edited::com);
  note_item("com");
  if (ImGui::InputDouble("weight P", &e.run.body.weight, 0.1, 1.0, "%.4g",
                         ImGuiInputTextFlags_EnterReturnsTrue))
    edited(Edited::weight);
  note_item("weight");
  // The initial state by its symbols, as the font can draw them.
  const std::string omega0 = render::drawable_text(std::string(physics::symbol::omega) + "(0)");
  const std::string gamma0 = render::drawable_text(std::string(physics::symbol::gamma) + "(0)");
  if (ImGui::DragScalarN(omega0.c_str(), ImGuiDataType_Double, e.run.initial.omega.data(), 3, 0.01f,
                         nullptr, nullptr, "%.4g"))
    edited(Edited::omega);
  note_item("omega");
  if (ImGui::DragScalarN(gamma0.c_str(), ImGuiDataType_Double, e.run.initial.gamma.data(), 3, 0.01f,
                         nullptr, nullptr, "%.4g")) {
    // gamma is a unit vector: the edit sets its direction.
    const double n = e.run.initial.gamma.norm();
    if (n > 1e-9) e.run.initial.gamma /= n;
    edited(Edited::gamma);
  }
  note_item("gamma");
}

void ControlPanel::draw_integrator(const LiveScene& scene, PanelActions& out) {
  const LiveSetup& s = scene.setup();
  LiveSetup e = s;
  // The formulation the scene runs, which the view may have chosen (the
  // space view needs the spinor form) rather than the one in the setup.
  const sim::Formulation running = scene.formulation();
  shown_formulation_ = running;
  if (ImGui::BeginCombo("formulation", std::string(sim::name(running)).c_str())) {
    note_window("list:formulation");
    for (auto f : sim::all_formulations()) {
      const bool usable = !sim::incompatibility(s.run.method, f) &&
                          (s.scene.view != scene::View::space || f == sim::Formulation::spinor);
      if (!usable) ImGui::BeginDisabled();
      if (ImGui::Selectable(std::string(sim::name(f)).c_str(), f == running)) {
        e.run.formulation = f;
        e.scene.formulation_given = true;
        out.rerun = e;
      }
      note_item(("formulation:" + std::string(sim::name(f))).c_str());
      if (!usable) ImGui::EndDisabled();
    }
    ImGui::EndCombo();
  }
  note_item("formulation");
  if (ImGui::BeginCombo("method", std::string(sim::name(s.run.method)).c_str())) {
    note_window("list:method");
    for (auto m : sim::all_methods()) {
      const bool usable = !sim::incompatibility(m, s.run.formulation);
      if (!usable) ImGui::BeginDisabled();
      if (ImGui::Selectable(std::string(sim::name(m)).c_str(), m == s.run.method)) {
        e.run.method = m;
        out.rerun = e;
      }
      note_item(("method:" + std::string(sim::name(m))).c_str());
      if (!usable) ImGui::EndDisabled();
    }
    ImGui::EndCombo();
  }
  note_item("method");
  if (sim::is_adaptive(s.run.method)) {
    bool automatic = s.scene.auto_tolerance;
    if (ImGui::Checkbox("tolerance from resolution", &automatic)) {
      e.scene.auto_tolerance = automatic;
      out.rerun = e;
    }
    note_item("auto_tol");
    if (!automatic) {
      if (log_slider("tolerance", &e.run.tol, 1e-13, 1e-3, "%.1e")) out.rerun = e;
      note_item("run_tol");
    }
  } else {
    if (log_slider("step", &e.run.step, 1e-4, 0.5, "%.2e")) out.rerun = e;
    note_item("run_step");
  }
  if (s.run.formulation == sim::Formulation::riccati &&
      ImGui::Checkbox("chart switch", &e.run.chart_switch))
    out.rerun = e;
}

void ControlPanel::draw_view(const LiveScene& scene, PanelActions& out) {
  const LiveSetup& s = scene.setup();
  LiveSetup e = s;
  int view = s.scene.view == scene::View::space ? 1 : 0;
  bool view_changed = ImGui::RadioButton("body frame", &view, 0);
  ImGui::SameLine();
  view_changed |= ImGui::RadioButton("space frame", &view, 1);
  if (view_changed) {
    e.scene.view = view == 1 ? scene::View::space : scene::View::body;
    // The space view needs the attitude, which only the spinor form carries.
    if (e.scene.view == scene::View::space) e.run.formulation = sim::Formulation::spinor;
    out.rerun = e;
  }
  bool layers_changed = false;
  for (std::size_t i = 0; i < scene::layer_count; ++i) {
    const auto& l = scene::layer_table()[i];
    if (i % 3 != 0) ImGui::SameLine();  // three checkboxes a row
    layers_changed |= ImGui::Checkbox(l.panel_label, &(e.scene.layers.*l.member));
  }
  if (layers_changed && e.scene.layers.any()) out.view = e;
  if (drag_double("trail length", &e.scene.trail_length, 0.1, kMinTrailLength, kMaxTrailLength,
                  "%.3g"))
    out.rerun = e;
  note_item("trail");
  if (ImGui::Button("Reset camera")) {
    e.scene.camera = scene::CameraSettings{};
    out.view = e;
  }
  ImGui::SameLine();
  ImGui::TextDisabled("drag: orbit, wheel: zoom");
}

void ControlPanel::draw_section(const LiveScene& scene, PanelActions& out) {
  const LiveSetup& s = scene.setup();
  if (s.scene.section) last_section_ = s.scene.section;
  bool shown = s.scene.section.has_value();
  if (ImGui::Checkbox("show the section panel", &shown)) {
    LiveSetup e = s;
    if (shown) {
      // Its surface and axes again; not its orbits, which may lie on the
      // level of a run edited since.
      e.scene.section = last_section_.value_or(scene::SectionPanelSettings{});
      e.scene.section->orbits.clear();
    } else
      e.scene.section.reset();
    out.view = e;
  }
  note_item("section");
  const LiveSection* section = scene.section();
  if (!section) return;
  if (auto why = section->clicks_refused()) {
    ImGui::TextWrapped("%s", render::drawable_text(*why).c_str());
    return;
  }
  ImGui::TextWrapped("%s", render::drawable_text("A click on the panel starts an orbit there, on "
                                                 "this run's level of C₁ and C₀ and on the sheet "
                                                 "drawn.")
                               .c_str());
  // One sheet: the one drawn is the one a click starts on.
  const scene::SectionPanelSettings& drawn = section->settings();
  const auto sheet = sim::chart_sheet_component(drawn.surface, drawn.coords);
  if (drawn.sheet && drawn.sheet->component == *sheet) click_sheet_ = drawn.sheet->sign;
  const std::string name(sim::symbol(*sheet));
  const int was = click_sheet_;
  ImGui::TextUnformatted("sheet");
  ImGui::SameLine();
  ImGui::RadioButton(render::drawable_text(name + " > 0").c_str(), &click_sheet_, 1);
  note_item("sheet:+");
  ImGui::SameLine();
  ImGui::RadioButton(render::drawable_text(name + " < 0").c_str(), &click_sheet_, -1);
  note_item("sheet:-");
  if (click_sheet_ != was) {
    LiveSetup e = s;
    e.scene.section->sheet = scene::SectionSheet{*sheet, click_sheet_};
    out.view = e;
  }
  ImGui::Text("orbits: %d of %d", section->orbit_count(), scene::kMaxSectionOrbits);
  ImGui::SameLine();
  if (ImGui::Button("Clear orbits")) out.clear_orbits = true;
  note_item("clear_orbits");
}

void ControlPanel::draw_drift(const LiveScene& scene) {
  const auto& history = scene.drift_history();
  if (history.empty()) return;
  const sim::Drifts& now = history.back().drift;
  const sim::Drifts& worst = scene.max_drift();
  const std::string names[] = {std::string(physics::symbol::gamma_norm2),
                               std::string(physics::symbol::area) + " (area)",
                               std::string(physics::symbol::energy) + " (energy)"};
  const double values[] = {now.gamma_norm2, now.area, now.energy};
  const double maxima[] = {worst.gamma_norm2, worst.area, worst.energy};
  const std::string extra_name = scene::extra_integral_symbol(scene.setup().run.case_id);
  const int rows = now.extra ? 4 : 3;
  ImGui::TextDisabled("%s", render::drawable_text("log₁₀ relative drift over the last " +
                                                  std::to_string(history.size()) + " frames")
                                .c_str());
  for (int i = 0; i < rows; ++i) {
    const double v = i < 3 ? values[i] : *now.extra;
    const double m = i < 3 ? maxima[i] : worst.extra.value_or(0.0);
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "%.1e (max %.1e)", v, m);
    PlotData data{&history, i};
    ImGui::PushStyleColor(ImGuiCol_PlotLines, to_imgui(kTheme.drift_colour(m)));
    const std::string name = render::drawable_text(i < 3 ? names[i] : extra_name);
    ImGui::PlotLines(name.c_str(), drift_log10, &data, int(history.size()), 0, overlay, -17.0f,
                     0.0f, ImVec2(0, 2.4f * ImGui::GetFontSize()));
    ImGui::PopStyleColor();
  }
}

void ControlPanel::draw_runs(const LiveScene& scene, PanelActions& out) {
  const LiveSetup& s = scene.setup();
  // The legend's rows as the picture shows them, each in its run's colour.
  const auto& comparison = scene.frame().comparison;
  const int runs = scene.run_count();
  for (int i = 0; i < runs; ++i) {
    const std::string row_name = "run:" + std::to_string(i + 1);
    const std::string text =
        comparison && std::size_t(i) < comparison->labels.size()
            ? comparison->labels[std::size_t(i)]
            : std::string(sim::name(s.run.method)) + ", " + scene.accuracy_note();
    // The button first, so that a long row never pushes it out of the panel.
    if (i > 0) {
      const std::string remove = "remove##" + std::to_string(i + 1);
      if (ImGui::SmallButton(remove.c_str())) {
        LiveSetup e = s;
        e.compared.erase(e.compared.begin() + (i - 1));
        out.rerun = e;
      }
      note_item(("remove:" + std::to_string(i + 1)).c_str());
      ImGui::SameLine();
    }
    ImGui::PushStyleColor(ImGuiCol_Text, to_imgui(scene::run_colour(i, false)));
    ImGui::TextWrapped("%d: %s", i + 1, text.c_str());
    ImGui::PopStyleColor();
    note_item(row_name.c_str());
  }
  const bool full = runs >= kMaxLiveRuns;
  if (full) ImGui::TextDisabled("at most %d runs", kMaxLiveRuns);
  // Another method, with its own step or tolerance.
  const sim::Method method = new_method_.value_or(s.run.method);
  if (ImGui::BeginCombo("method##new", std::string(sim::name(method)).c_str())) {
    note_window("list:new_method");
    for (auto m : sim::all_methods()) {
      const bool usable = !sim::incompatibility(m, scene.formulation());
      if (!usable) ImGui::BeginDisabled();
      if (ImGui::Selectable(std::string(sim::name(m)).c_str(), m == method)) new_method_ = m;
      note_item(("new_method:" + std::string(sim::name(m))).c_str());
      if (!usable) ImGui::EndDisabled();
    }
    ImGui::EndCombo();
  }
  note_item("new_method");
  if (sim::is_adaptive(method)) {
    log_slider("tolerance##new", &new_tol_, 1e-13, 1e-3, "%.1e");
    note_item("new_tol");
  } else {
    log_slider("step##new", &new_step_, 1e-4, 0.5, "%.2e");
    note_item("new_step");
  }
  if (full) ImGui::BeginDisabled();
  if (ImGui::Button("Add run")) {
    LiveSetup e = s;
    e.compared.push_back(with_method(method, new_step_, new_tol_));
    out.rerun = e;
  }
  if (full) ImGui::EndDisabled();
  note_item("add_run");
  // The first run's state, nudged.
  log_slider("nudge (rad)", &nudge_, kMinNudge, kMaxNudge, "%.1e");
  note_item("nudge");
  if (full) ImGui::BeginDisabled();
  if (ImGui::Button("Add nudged run")) {
    LiveSetup e = s;
    e.compared.push_back(nudged_by(nudge_));
    out.rerun = e;
  }
  if (full) ImGui::EndDisabled();
  note_item("add_nudged");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "%s", render::drawable_text("the first run with " + std::string(physics::symbol::gamma) +
                                    "(0) turned by the nudge: " +
                                    std::string(physics::symbol::separation) + " starts there")
                  .c_str());
  ImGui::TextDisabled("every run starts again at t = 0");
}

void ControlPanel::draw_save() {
  char name[64];
  std::snprintf(name, sizeof name, "%s", save_name_.c_str());
  if (ImGui::InputText("##file name", name, sizeof name)) {
    std::string n = name;
    n.erase(std::remove_if(n.begin(), n.end(), [](char c) { return c == '/' || c == '\\'; }),
            n.end());
    if (!n.empty()) save_name_ = n;
  }
  note_item("file_name");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("file name: frames <name>_t<time>.png, jobs <name>.json");
}

}  // namespace epviz::live
