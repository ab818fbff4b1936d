#include "paint/figure_common.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <span>

#include "render/panel_2d.hpp"

namespace epviz::paint {

float chart_font_px(const ChartOptions& options) {
  if (options.builtin_font) return 13.0f;
  if (options.font_px > 0.0f) return options.font_px;
  return std::clamp(float(options.height) / 40.0f, 13.0f, 30.0f);
}

std::string power_of_ten(int exponent) {
  static const char* const digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string text = "10";
  if (exponent < 0) text += "⁻";
  for (char c : std::to_string(std::abs(exponent))) text += digits[c - '0'];
  return text;
}

std::string decade_label(int exponent) { return power_of_ten(exponent); }

std::string print_minus(std::string text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    const bool minus =
        text[i] == '-' && (std::isdigit(static_cast<unsigned char>(next)) || next == '.');
    // Not a hyphen inside a word or a name ("Gauss-4", "RK-45").
    const bool in_word = i > 0 && std::isalnum(static_cast<unsigned char>(text[i - 1]));
    out += minus && !in_word ? "−" : std::string(1, text[i]);
  }
  return out;
}

std::string print_number(double value, int significant) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", std::clamp(significant, 1, 17), value);
  std::string text = buf;
  const auto e = text.find_first_of("eE");
  if (e == std::string::npos) return print_minus(text);
  const int exponent = std::atoi(text.c_str() + e + 1);
  std::string mantissa = text.substr(0, e);
  // "1e-08" is 10⁻⁸, not 1×10⁻⁸.
  if (mantissa == "1" || mantissa == "-1")
    return (mantissa == "1" ? "" : "−") + power_of_ten(exponent);
  return print_minus(mantissa) + "×" + power_of_ten(exponent);
}

std::string print_scientific(double value, int decimals) {
  if (!std::isfinite(value))
    return std::isnan(value) ? "nan" : print_minus(value < 0 ? "-inf" : "inf");
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*e", std::clamp(decimals, 0, 16), value);
  const std::string text = buf;
  const auto e = text.find('e');
  return print_minus(text.substr(0, e)) + "×" + power_of_ten(std::atoi(text.c_str() + e + 1));
}

void Span::add(double v) {
  if (std::isfinite(v)) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
}

void finish_span(Span& s, bool log_axis) {
  if (s.empty()) {
    s.lo = log_axis ? -1.0 : 0.0;
    s.hi = log_axis ? 1.0 : 1.0;
    return;
  }
  if (log_axis) {
    s.lo = std::floor(s.lo + 1e-9);
    s.hi = std::ceil(s.hi - 1e-9);
    if (s.hi <= s.lo) s.hi = s.lo + 1.0;
    return;
  }
  if (s.hi - s.lo < 1e-300) {
    const double pad = std::max(std::abs(s.lo) * 0.1, 1.0);
    s.lo -= pad;
    s.hi += pad;
  }
  const double pad = 0.04 * (s.hi - s.lo);
  s.lo -= pad;
  s.hi += pad;
}

std::vector<Tick> axis_ticks(double lo, double hi, bool log_axis, int max_labels) {
  std::vector<Tick> ticks;
  if (log_axis) {
    const int first = int(std::ceil(lo - 1e-9)), last = int(std::floor(hi + 1e-9));
    const int decades = last - first;
    const int step =
        std::max(1, int(std::ceil(double(decades) / double(std::max(1, max_labels - 1)))));
    for (int e = first; e <= last; ++e) {
      const bool labelled = (e - first) % step == 0;
      ticks.push_back({double(e), labelled ? decade_label(e) : std::string(), true});
      if (step == 1 && decades <= 8 && e < last)
        for (int m = 2; m <= 9; ++m)
          ticks.push_back({double(e) + std::log10(double(m)), {}, false});
    }
    return ticks;
  }
  const auto values = render::nice_ticks(lo, hi, max_labels);
  const double spacing = values.size() > 1 ? values[1] - values[0] : (hi - lo);
  for (double v : values) ticks.push_back({v, print_minus(render::format_tick(v, spacing)), true});
  return ticks;
}

void draw_axes_in_print(const render::Panel2D& plot, render::DrawList& list,
                        const render::PanelStyle& style) {
  // Drawn apart, then added: a DrawList's labels are not edited in place.
  render::DrawList axes;
  plot.draw_axes(axes, style);
  if (!axes.triangles().empty()) list.add_triangles(axes.triangles());
  const auto& vertices = axes.line_vertices();
  for (const auto& p : axes.polylines())
    list.add_polyline(std::span(vertices).subspan(p.first, p.count), p.width_px, p.closed);
  for (const auto& m : axes.markers()) list.add_marker(m);
  for (const auto& d : axes.dots())
    list.add_dots(std::span(axes.dot_vertices()).subspan(d.first, d.count), d.size_px);
  for (auto l : axes.labels()) {
    l.text = print_minus(l.text);
    list.add_text(std::move(l));
  }
}

namespace {

// `word` cut into pieces no wider than `max_width`, each at least one
// character (a UTF-8 sequence is never split).
std::vector<std::string> break_characters(const std::string& word, const ChartFont& font,
                                          float max_width) {
  std::vector<std::string> pieces;
  std::string piece;
  for (std::size_t i = 0; i < word.size();) {
    std::size_t n = 1;
    while (i + n < word.size() && (static_cast<unsigned char>(word[i + n]) & 0xC0) == 0x80) ++n;
    const std::string ch = word.substr(i, n);
    if (!piece.empty() && font.width(piece + ch) > max_width) {
      pieces.push_back(piece);
      piece.clear();
    }
    piece += ch;
    i += n;
  }
  if (!piece.empty()) pieces.push_back(piece);
  return pieces;
}

// `word` cut after its soft breaks into pieces no wider than `max_width`,
// joined again where they fit; a piece too wide alone broken between characters.
std::vector<std::string> break_word(const std::string& word, const ChartFont& font,
                                    float max_width) {
  std::vector<std::string> soft;
  std::string piece;
  for (char c : word) {
    piece += c;
    if (is_soft_break(c)) {
      soft.push_back(piece);
      piece.clear();
    }
  }
  if (!piece.empty()) soft.push_back(piece);
  std::vector<std::string> pieces;
  std::string current;
  for (const auto& s : soft) {
    if (font.width(current + s) <= max_width) {
      current += s;
      continue;
    }
    if (!current.empty()) pieces.push_back(current);
    current.clear();
    auto chars = break_characters(s, font, max_width);
    current = chars.back();
    chars.pop_back();
    pieces.insert(pieces.end(), chars.begin(), chars.end());
  }
  if (!current.empty()) pieces.push_back(current);
  return pieces;
}

}  // namespace

bool is_soft_break(char c) { return c == '_' || c == '-' || c == '+' || c == ',' || c == '/'; }

std::vector<std::string> wrap_text(const std::string& text, const ChartFont& font,
                                   float max_width) {
  if (text.empty()) return {};
  if (font.width(text) <= max_width) return {text};
  std::vector<std::string> lines;
  std::string current;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t space = text.find(' ', start);
    const std::string word =
        text.substr(start, space == std::string::npos ? std::string::npos : space - start);
    start = space == std::string::npos ? text.size() + 1 : space + 1;
    if (word.empty()) continue;
    const std::string joined = current.empty() ? word : current + " " + word;
    if (font.width(joined) <= max_width) {
      current = joined;
      continue;
    }
    if (!current.empty()) lines.push_back(current);
    current.clear();
    auto pieces = break_word(word, font, max_width);
    current = pieces.back();
    pieces.pop_back();
    lines.insert(lines.end(), pieces.begin(), pieces.end());
  }
  if (!current.empty()) lines.push_back(current);
  return lines;
}

render::TextLabel label(glm::vec2 at, std::string text, render::TextAnchor anchor,
                        glm::vec4 colour) {
  render::TextLabel l;
  l.position = glm::vec3(at, 0.0f);
  l.text = std::move(text);
  l.colour = colour;
  l.anchor = anchor;
  return l;
}

}  // namespace epviz::paint
