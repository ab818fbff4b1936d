#pragma once
// Text as the picture's font can draw it. Labels name quantities by their
// symbols (γ, Ω₃, |γ|², C₁, −); a font without one of their glyphs (ImGui's
// bitmap font, which snapshot tests use) would draw it as '?'. The choice is
// made here, for every text an overlay draws or measures: a text the font can
// draw whole is kept, any other is spelled in ASCII as a whole, so that a
// label never mixes the two notations.
#include <string>
#include <string_view>

struct ImFont;

namespace epviz::render {

// `utf8` in ASCII: Greek letters by their names ("γ₁" -> "gamma1", "Δγ" ->
// "Delta gamma"), sub- and superscripts as digits ("C₀" -> "C0", "|γ|²" ->
// "|gamma|^2", "10⁻⁸" -> "10^-8"), the minus sign and dashes as '-', a few
// operators as their ASCII forms ("≤" -> "<="); any other non-ASCII character
// as '?'.
std::string ascii_spelling(std::string_view utf8);

// Whether `font` has a glyph for every character of `utf8`.
bool font_has_glyphs(const ImFont& font, std::string_view utf8);

// `utf8` itself when `font` has all its glyphs, else its ASCII spelling.
std::string drawable_text(const ImFont& font, std::string_view utf8);
// The same in the font of the ImGui frame being built (ImGui windows' text).
std::string drawable_text(std::string_view utf8);

}  // namespace epviz::render
