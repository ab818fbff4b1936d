#include "render/font_text.hpp"

#include <imgui.h>

#include <array>
#include <cctype>

namespace epviz::render {
namespace {

// The next code point of `s` from `i` (advanced past it); a malformed byte
// is U+FFFD, one byte long.
char32_t next_code_point(std::string_view s, std::size_t& i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  const int length = lead < 0x80           ? 1
                     : (lead >> 5) == 0x6  ? 2
                     : (lead >> 4) == 0xE  ? 3
                     : (lead >> 3) == 0x1E ? 4
                                           : 0;
  if (length == 0 || i + std::size_t(length) > s.size()) {
    ++i;
    return 0xFFFD;
  }
  char32_t c = length == 1 ? lead : lead & (0x7F >> length);
  for (int k = 1; k < length; ++k) {
    if ((byte(i + std::size_t(k)) & 0xC0) != 0x80) {
      ++i;
      return 0xFFFD;
    }
    c = (c << 6) | (byte(i + std::size_t(k)) & 0x3F);
  }
  i += std::size_t(length);
  return c;
}

// U+0391..U+03A9 and U+03B1..U+03C9 (U+03A2 is unassigned, U+03C2 is the final sigma).
constexpr std::array<const char*, 25> kGreek = {
    "Alpha", "Beta",   "Gamma",   "Delta", "Epsilon", "Zeta",    "Eta",  "Theta", "Iota",
    "Kappa", "Lambda", "Mu",      "Nu",    "Xi",      "Omicron", "Pi",   "Rho",   "Sigma",
    "Sigma", "Tau",    "Upsilon", "Phi",   "Chi",     "Psi",     "Omega"};

// A Greek letter's name ("gamma", "Omega"), or empty.
std::string greek_name(char32_t c) {
  const bool upper = c >= 0x391 && c <= 0x3A9 && c != 0x3A2;
  const bool lower = c >= 0x3B1 && c <= 0x3C9;
  if (!upper && !lower) return {};
  std::string name = kGreek[std::size_t(c - (upper ? 0x391 : 0x3B1))];
  if (lower)
    for (char& ch : name) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return name;
}

// A superscript's ordinary character ('2' for '²'), or 0.
char superscript(char32_t c) {
  if (c == 0xB9) return '1';
  if (c == 0xB2) return '2';
  if (c == 0xB3) return '3';
  if (c == 0x2070) return '0';
  if (c >= 0x2074 && c <= 0x2079) return char('4' + (c - 0x2074));
  if (c == 0x207A) return '+';
  if (c == 0x207B) return '-';
  if (c == 0x207D) return '(';
  if (c == 0x207E) return ')';
  if (c == 0x207F) return 'n';
  return 0;
}

// A subscript's ordinary character ('1' for '₁'), or 0.
char subscript(char32_t c) {
  if (c >= 0x2080 && c <= 0x2089) return char('0' + (c - 0x2080));
  if (c == 0x208A) return '+';
  if (c == 0x208B) return '-';
  return 0;
}

// Other characters labels use, in ASCII; nullptr if none.
const char* other(char32_t c) {
  switch (c) {
    case 0x2212: return "-";  // minus sign
    case 0x2010:
    case 0x2011:
    case 0x2012:
    case 0x2013: return "-";
    case 0x2014:
    case 0x2015: return "--";
    case 0x2018:
    case 0x2019: return "'";
    case 0x201C:
    case 0x201D: return "\"";
    case 0x2026: return "...";
    case 0x2264: return "<=";
    case 0x2265: return ">=";
    case 0x2248: return "~";
    case 0x2260: return "!=";
    case 0x221E: return "inf";
    case 0x2192: return "->";
    case 0x2190: return "<-";
    case 0x00D7: return "x";
    case 0x00B7:
    case 0x22C5: return "*";
    case 0x00B1: return "+-";
    case 0x00B0: return " deg";
    case 0x00A0: return " ";
    default: return nullptr;
  }
}

}  // namespace

std::string ascii_spelling(std::string_view utf8) {
  std::string out;
  out.reserve(utf8.size() + 8);
  bool after_greek = false, in_superscript = false;
  for (std::size_t i = 0; i < utf8.size();) {
    const char32_t c = next_code_point(utf8, i);
    const char up = superscript(c);
    if (up != 0) {
      if (!in_superscript) out += '^';
      out += up;
      in_superscript = true;
      after_greek = false;
      continue;
    }
    in_superscript = false;
    const std::string name = greek_name(c);
    const bool letter = !name.empty() || (c < 0x80 && std::isalpha(int(c)));
    // "Δγ" reads "Delta gamma", not "Deltagamma".
    if (after_greek && letter) out += ' ';
    after_greek = !name.empty();
    if (!name.empty())
      out += name;
    else if (c < 0x80)
      out += char(c);
    else if (const char down = subscript(c); down != 0)
      out += down;
    else if (const char* spelled = other(c))
      out += spelled;
    else
      out += '?';
  }
  return out;
}

bool font_has_glyphs(const ImFont& font, std::string_view utf8) {
  for (std::size_t i = 0; i < utf8.size();) {
    const char32_t c = next_code_point(utf8, i);
    if (c < 0x80) continue;  // every font the overlay loads has ASCII
    if (c > 0xFFFF || font.FindGlyphNoFallback(ImWchar(c)) == nullptr) return false;
  }
  return true;
}

std::string drawable_text(const ImFont& font, std::string_view utf8) {
  if (font_has_glyphs(font, utf8)) return std::string(utf8);
  return ascii_spelling(utf8);
}

std::string drawable_text(std::string_view utf8) { return drawable_text(*ImGui::GetFont(), utf8); }

}  // namespace epviz::render
