// Labels name quantities by their symbols (physics/notation.hpp): γ, Ω, |γ|², C₀,
// C₁, Δγ, the components γ₁ ... Ω₃, the plane's caption a = −γ₁/(1+γ₃). The overlay's font (DejaVu Sans)
// has a glyph for each, so they are drawn as they are; ImGui's bitmap font has
// none of them, so there every such text is spelled in ASCII as a whole, and
// no character is drawn as the font's '?'.
#include <gtest/gtest.h>

#include <imgui.h>

#include <string>
#include <vector>

#include "paint/frame_painter.hpp"
#include "paint/preset_frame.hpp"
#include "physics/cases.hpp"
#include "physics/notation.hpp"
#include "render/font_text.hpp"
#include "render/gui_overlay.hpp"
#include "render/render_test_support.hpp"
#include "scene/frame_source.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;

// Every symbol text the pictures use, and the operators the keys use.
std::vector<std::string> symbol_texts() {
  std::vector<std::string> texts;
  for (const auto s : {physics::symbol::gamma, physics::symbol::omega, physics::symbol::gamma_norm2,
                       physics::symbol::area, physics::symbol::energy, physics::symbol::separation,
                       physics::symbol::riccati_projection, physics::symbol::infinity})
    texts.emplace_back(s);
  for (const auto s : physics::symbol::omega_component) texts.emplace_back(s);
  for (const auto s : physics::symbol::gamma_component) texts.emplace_back(s);
  for (const auto& p : physics::case_presets())
    if (const auto symbol = scene::extra_integral_symbol(p.id); !symbol.empty())
      texts.push_back(symbol);
  texts.insert(texts.end(), {"log₁₀", "Δγ = γ − γ of run 1", "≥1e-2"});
  return texts;
}

bool ascii_only(const std::string& s) {
  for (const char c : s)
    if (static_cast<unsigned char>(c) >= 0x80) return false;
  return true;
}

TEST(AsciiSpelling, SpellsSymbolsByTheirNames) {
  EXPECT_EQ(render::ascii_spelling("|γ|²"), "|gamma|^2");
  EXPECT_EQ(render::ascii_spelling("C₀ (area)"), "C0 (area)");
  EXPECT_EQ(render::ascii_spelling("C₁"), "C1");
  EXPECT_EQ(render::ascii_spelling("Ω₃"), "Omega3");
  EXPECT_EQ(render::ascii_spelling("a = −γ₁/(1+γ₃), b = −γ₂/(1+γ₃)"),
            "a = -gamma1/(1+gamma3), b = -gamma2/(1+gamma3)");
  EXPECT_EQ(render::ascii_spelling("log₁₀ |Δγ| over t"), "log10 |Delta gamma| over t");
  EXPECT_EQ(render::ascii_spelling("10⁻⁸ ≤ x, y ≥ 1e-2, ∞"), "10^-8 <= x, y >= 1e-2, inf");
  EXPECT_EQ(render::ascii_spelling("γ (body frame)"), "gamma (body frame)");
  EXPECT_EQ(render::ascii_spelling("plain text"), "plain text");
  // What it cannot spell, and bytes that are not UTF-8, are one '?' each.
  EXPECT_EQ(render::ascii_spelling("\xe2\x82"), "??");
  EXPECT_EQ(render::ascii_spelling("ж"), "?");
}

TEST(LabelSymbols, TheOverlaysFontDrawsEverySymbol) {
  paint::FramePainter painter(et::shared_gl_context(), 320, 180, {.builtin_font = false});
  const ImFont& font = *painter.gui().font();
  for (const auto& text : symbol_texts()) {
    EXPECT_TRUE(render::font_has_glyphs(font, text))
        << text << " in " << painter.gui().font_source();
    EXPECT_EQ(render::drawable_text(font, text), text);
  }
}

TEST(LabelSymbols, TheBitmapFontDrawsThemInAscii) {
  paint::FramePainter painter(et::shared_gl_context(), 320, 180, {.builtin_font = true});
  const ImFont& font = *painter.gui().font();
  EXPECT_FALSE(render::font_has_glyphs(font, "γ"));
  for (const auto& text : symbol_texts()) {
    const std::string drawn = render::drawable_text(font, text);
    // Drawn as it is where the font has every glyph (Latin-1's ²), else in ASCII.
    EXPECT_TRUE(drawn == text || ascii_only(drawn)) << text << " -> " << drawn;
    EXPECT_EQ(drawn.find('?'), std::string::npos) << text << " -> " << drawn;
    EXPECT_TRUE(render::font_has_glyphs(font, drawn)) << drawn;
  }
  // Measured as drawn: the ASCII spelling's width, not the symbols'.
  EXPECT_EQ(painter.gui().text_size(std::string(physics::symbol::riccati_projection)).x,
            painter.gui().text_size("a = -gamma1/(1+gamma3), b = -gamma2/(1+gamma3)").x);
}

// A frame's texts, as the painter placed them, all in the font's glyphs.
TEST(LabelSymbols, EveryTextOfAFrameHasItsGlyphs) {
  paint::FramePainter painter(et::shared_gl_context(), 1280, 720, {.builtin_font = false});
  scene::SceneSettings s;
  s.width = 1280, s.height = 720, s.trail_length = 6.0;
  const auto f = et::preset_frame(physics::Case::kovalevskaya, s);
  painter.paint(f);
  const ImFont& font = *painter.gui().font();
  std::vector<std::string> texts = {f.overlay.title, f.trail_label};
  for (const auto& [name, value] : f.overlay.drifts) texts.push_back(name);
  for (const auto& l : painter.annotations().labels) texts.push_back(l.text);
  for (const auto& l : painter.annotations().legend) texts.push_back(l.text);
  bool symbols = false;
  for (const auto& t : texts) {
    EXPECT_TRUE(render::font_has_glyphs(font, t)) << t;
    symbols |= !ascii_only(t);
  }
  EXPECT_TRUE(symbols) << "no text of the frame uses a symbol: the check is moot";
  EXPECT_EQ(f.overlay.drifts.front().first, "|γ|²");
  EXPECT_EQ(f.trail_label, "γ (body frame)");
}

}  // namespace
}  // namespace epviz
