#pragma once
// The ImGui overlay: its own ImGui context, a font, a fixed time step (frames
// are rendered, not lived, so time must not come from a clock), and text
// labels placed anywhere in the image through the foreground draw list.
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "render/draw_list.hpp"

struct ImGuiContext;
struct ImFont;

namespace epviz::render {

class ImGuiGlRenderer;

struct OverlayOptions {
  // Font file (TTF/OTF). Empty: $EPVIZ_FONT, else assets/fonts/overlay.ttf if
  // shipped, else the system's DejaVu Sans; none of them: the constructor
  // throws, naming the package (no silent fallback to another font).
  std::filesystem::path font_file;
  // Force ImGui's built-in bitmap font (13 px); snapshot tests use it so that
  // they do not depend on which fonts a machine has.
  bool builtin_font = false;
  float font_size_px = 16.0f;
  // Paddings, spacings and roundings are multiplied by this (big pictures);
  // the built-in font, which has one size, is magnified by its whole part.
  float ui_scale = 1.0f;
  bool light_style = false;  // ImGui's light colours instead of dark
  float delta_time_s = 1.0f / 30.0f;
};

// The font an overlay with no font_file and no builtin_font uses, as its
// font_source() names it ("builtin" or a path), found without GL; throws as
// the constructor does when there is none.
std::string default_overlay_font();

// A label already placed in image pixels (top-left origin).
struct PlacedLabel {
  glm::vec2 pixel;
  const TextLabel* label;
};

class ImGuiOverlay {
 public:
  explicit ImGuiOverlay(const OverlayOptions& options = {});  // needs a current GL context
  ~ImGuiOverlay();
  ImGuiOverlay(const ImGuiOverlay&) = delete;
  ImGuiOverlay& operator=(const ImGuiOverlay&) = delete;

  // One ImGui frame of width x height: calls `build_ui` (ImGui::Begin()... may
  // be used inside), adds `labels` on the foreground draw list and draws into
  // the bound framebuffer. The first call runs a hidden warm-up frame first,
  // because ImGui does not draw a new window on the frame it appears.
  void draw_frame(int width, int height, const std::function<void()>& build_ui,
                  std::span<const PlacedLabel> labels = {});
  // Runs `build_ui` in a frame that is not drawn (windows get their size).
  void warm_up(int width, int height, const std::function<void()>& build_ui);

  // The font in use, and where it came from ("builtin" or a path).
  ImFont* font() const { return font_; }
  const std::string& font_source() const { return font_source_; }
  ImGuiContext* context() const { return context_; }
  // The size of `text` as labels and windows draw it, in pixels; usable
  // outside an ImGui frame (label placement happens before the overlay runs).
  glm::vec2 text_size(const std::string& text) const;
  // The height of a line of label text.
  float label_font_px() const;
  // The time step ImGui is told for the next frames (interactive use passes
  // the wall-clock time between frames; renders keep the fixed one).
  void set_delta_time(float seconds) { options_.delta_time_s = seconds; }
  // Frames of width x height pixels hold a layout of width/scale x
  // height/scale (ImGui's framebuffer scale): the interface is laid out as at
  // full size and drawn smaller, so every control lies at the same place
  // relative to the frame at any scale (a live view drawn smaller while it
  // moves, which the page stretches back). Positions ImGui is given and
  // gives are then in layout units: frame pixels / scale. Labels and
  // text_size() stay in frame pixels.
  void set_framebuffer_scale(float scale) { framebuffer_scale_ = scale; }
  float framebuffer_scale() const { return framebuffer_scale_; }

 private:
  void begin(int width, int height);
  void add_labels(std::span<const PlacedLabel> labels);

  ImGuiContext* context_ = nullptr;
  float framebuffer_scale_ = 1.0f;
  ImFont* font_ = nullptr;
  std::string font_source_;
  std::unique_ptr<ImGuiGlRenderer> gl_renderer_;
  OverlayOptions options_;
  bool warmed_up_ = false;
};

// The top-left corner at which a box of `size` must start so that its
// `anchor` point lands on `point`.
glm::vec2 anchored_top_left(const glm::vec2& point, const glm::vec2& size, TextAnchor anchor);

}  // namespace epviz::render
