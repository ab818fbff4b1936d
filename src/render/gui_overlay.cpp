#include "render/gui_overlay.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <vector>

#include "io/data_dir.hpp"
#include "render/font_text.hpp"
#include "render/gl.hpp"
#include "render/imgui_context_scope.hpp"
#include "render/imgui_gl_renderer.hpp"

namespace epviz::render {
namespace {

constexpr const char* kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// The font the overlay uses when the caller names none: $EPVIZ_FONT if set (a
// file, or "builtin" for ImGui's bitmap font), else one shipped in assets/ if
// the project has one, else DejaVu Sans. Never a silent fallback: pictures
// drawn with another font differ from every golden made with this one, so a
// machine without the font fails here, naming the package that brings it.
std::filesystem::path default_font_file(bool& builtin) {
  if (const char* chosen = std::getenv("EPVIZ_FONT"); chosen != nullptr && *chosen != '\0') {
    if (std::string_view(chosen) == "builtin") {
      builtin = true;
      return {};
    }
    return chosen;
  }
  if (auto shipped = io::find_data_path("assets/fonts/overlay.ttf"); !shipped.empty())
    return shipped;
  const std::filesystem::path dejavu = kDejaVuSans;
  std::error_code error;
  if (std::filesystem::is_regular_file(dejavu, error)) return dejavu;
  throw std::runtime_error(
      "no font for the text in pictures: " + dejavu.string() +
      " is missing; install the Debian package fonts-dejavu-core, or set EPVIZ_FONT to a "
      "TTF file (or to 'builtin' for ImGui's bitmap font, which renders differently)");
}

std::string cannot_load(const std::filesystem::path& font) {
  return "cannot load the font '" + font.string() +
         "' for the text in pictures (a TTF or OTF file)";
}

// The characters a label may use beyond ImGui's default (Latin-1): axis
// titles and legends name physical quantities (γ, Ω, Δγ, ω₃, C₀, |γ|², 10⁻⁸,
// ≤, −, →, ∞). Only the glyphs the font has are baked; a text with one the
// font lacks is drawn in ASCII (render/font_text.hpp).
const ImWchar* label_glyph_ranges() {
  static const ImWchar ranges[] = {
      0x0020, 0x00FF,  // Basic Latin, Latin-1 (², ³, ·, °, ±, ×)
      0x0370, 0x03FF,  // Greek
      0x2010, 0x2044,  // dashes, quotes, bullets, primes, fraction slash
      0x2070, 0x209F,  // superscripts and subscripts
      0x2100, 0x214F,  // letterlike symbols (ℏ, Å)
      0x2190, 0x21FF,  // arrows
      0x2200, 0x22FF,  // mathematical operators (−, ≈, ≤, ∞, ∂)
      0,
  };
  return ranges;
}

ImU32 to_imgui_colour(const glm::vec4& c) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a));
}

}  // namespace

std::string default_overlay_font() {
  bool builtin = false;
  const auto file = default_font_file(builtin);
  if (builtin) return "builtin";
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) throw std::runtime_error(cannot_load(file));
  return file.string();
}

glm::vec2 anchored_top_left(const glm::vec2& point, const glm::vec2& size, TextAnchor anchor) {
  const int index = static_cast<int>(anchor);
  const float fx = static_cast<float>(index % 3) * 0.5f;  // 0 left, 0.5 centre, 1 right
  const float fy = static_cast<float>(index / 3) * 0.5f;  // 0 top, 0.5 middle, 1 bottom
  return {point.x - fx * size.x, point.y - fy * size.y};
}

ImGuiOverlay::ImGuiOverlay(const OverlayOptions& options) : options_(options) {
  IMGUI_CHECKVERSION();
  // CreateContext leaves the new context current when none was; this one is
  // made current only in scopes, so that none outlives it as ImGui's current
  // context (a later ImGui allocation would count itself in the freed one).
  ImGuiContext* const previous = ImGui::GetCurrentContext();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(previous);
  ImGuiContextScope scope(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini: a render must not depend on or leave state
  io.LogFilename = nullptr;
  if (options.light_style)
    ImGui::StyleColorsLight();
  else
    ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 4.0f;
  if (options.ui_scale > 1.0f) ImGui::GetStyle().ScaleAllSizes(options.ui_scale);

  bool builtin = options.builtin_font;
  std::filesystem::path file = builtin ? std::filesystem::path() : options.font_file;
  if (!builtin && file.empty()) {
    try {
      file = default_font_file(builtin);
    } catch (...) {
      ImGui::DestroyContext(context_);
      throw;
    }
  }
  if (!builtin) {
    std::error_code error;
    if (std::filesystem::is_regular_file(file, error))
      font_ = io.Fonts->AddFontFromFileTTF(file.c_str(), options.font_size_px, nullptr,
                                           label_glyph_ranges());
    if (font_ == nullptr) {
      ImGui::DestroyContext(context_);
      throw std::runtime_error(cannot_load(file));
    }
    font_source_ = file.string();
  } else {
    font_ = io.Fonts->AddFontDefault();
    font_source_ = "builtin";
    // A bitmap font: whole magnifications keep its glyphs crisp.
    io.FontGlobalScale = std::max(1.0f, std::round(options.ui_scale));
  }
  try {
    gl_renderer_ = std::make_unique<ImGuiGlRenderer>();
  } catch (...) {
    ImGui::DestroyContext(context_);
    throw;
  }
}

ImGuiOverlay::~ImGuiOverlay() {
  {
    ImGuiContextScope scope(context_);
    gl_renderer_.reset();  // needs the ImGui context alive
  }
  // Outside the scope, which would make the freed context current again on
  // leaving: DestroyContext keeps the current context, or none if it was this one.
  ImGui::DestroyContext(context_);
}

float ImGuiOverlay::label_font_px() const {
  ImGuiContextScope scope(context_);
  return font_->FontSize * ImGui::GetIO().FontGlobalScale * framebuffer_scale_;
}

glm::vec2 ImGuiOverlay::text_size(const std::string& text) const {
  const std::string drawn = drawable_text(*font_, text);
  const ImVec2 s = font_->CalcTextSizeA(label_font_px(), FLT_MAX, 0.0f, drawn.c_str());
  return {s.x, s.y};
}

void ImGuiOverlay::begin(int width, int height) {
  ImGuiIO& io = ImGui::GetIO();
  const float scale = framebuffer_scale_;
  io.DisplaySize = ImVec2(static_cast<float>(width) / scale, static_cast<float>(height) / scale);
  io.DisplayFramebufferScale = ImVec2(scale, scale);
  io.DeltaTime = options_.delta_time_s;
  ImGui::NewFrame();
}

void ImGuiOverlay::warm_up(int width, int height, const std::function<void()>& build_ui) {
  ImGuiContextScope scope(context_);
  begin(width, height);
  if (build_ui) build_ui();
  ImGui::EndFrame();
  warmed_up_ = true;
}

void ImGuiOverlay::add_labels(std::span<const PlacedLabel> labels) {
  // Behind every window: a label of the scene must not print over the overlay's text.
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  ImFont* font = ImGui::GetFont();
  const float size = ImGui::GetFontSize();
  const float scale = framebuffer_scale_;  // labels are placed in frame pixels
  for (const auto& placed : labels) {
    const TextLabel& label = *placed.label;
    const std::string text = drawable_text(*font, label.text);
    const ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, 0.0f, text.c_str());
    const glm::vec2 top_left = anchored_top_left(
        placed.pixel + label.offset_px, glm::vec2(extent.x, extent.y) * scale, label.anchor);
    // Whole pixels keep bitmap-like glyphs crisp.
    const ImVec2 at(std::round(top_left.x) / scale, std::round(top_left.y) / scale);
    if (label.background.a > 0.0f) {
      const float pad = 3.0f;
      draw->AddRectFilled(ImVec2(at.x - pad, at.y - pad + 1.0f),
                          ImVec2(at.x + extent.x + pad, at.y + extent.y + pad - 1.0f),
                          to_imgui_colour(label.background), 3.0f);
    }
    draw->AddText(font, size, at, to_imgui_colour(label.colour), text.c_str());
  }
}

void ImGuiOverlay::draw_frame(int width, int height, const std::function<void()>& build_ui,
                              std::span<const PlacedLabel> labels) {
  if (!warmed_up_) warm_up(width, height, build_ui);
  ImGuiContextScope scope(context_);
  begin(width, height);
  if (build_ui) build_ui();
  add_labels(labels);
  ImGui::Render();
  gl_renderer_->render(*ImGui::GetDrawData(), width, height);
}

}  // namespace epviz::render
