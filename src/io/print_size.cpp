#include "io/print_size.hpp"

#include <cmath>
#include <cstdio>

#include "io/bad_input.hpp"
#include "io/option_values.hpp"
#include "io/printable.hpp"

namespace epviz::io {
namespace {

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

double in_range(const std::string& option, const std::string& text, double value, double lo,
                double hi, const std::string& unit) {
  if (!(value >= lo && value <= hi))
    throw BadInput(option + ": '" + printable(text) + "' is outside " + number_text(lo) + unit +
                   " to " + number_text(hi) + unit);
  return value;
}

}  // namespace

int PrintSize::width_units() const { return int(std::lround(width_pt * units_per_pt())); }

float PrintSize::font_units() const { return float(font_pt * units_per_pt()); }

double parse_length_pt(const std::string& option, const std::string& text) {
  struct Unit {
    const char* name;
    double pt;
  };
  static constexpr Unit units[] = {
      {"mm", 72.0 / 25.4}, {"cm", 720.0 / 25.4}, {"in", 72.0}, {"pt", 1.0}};
  for (const auto& u : units) {
    const std::string suffix = u.name;
    if (text.size() <= suffix.size() || text.compare(text.size() - 2, 2, suffix) != 0) continue;
    double number = 0.0;
    try {
      number = parse_number(option, text.substr(0, text.size() - 2));
    } catch (const BadInput&) {
      break;
    }
    const double pt = number * u.pt;
    if (!(pt >= kMinFigureWidthPt && pt <= kMaxFigureWidthPt))
      throw BadInput(option + ": '" + printable(text) + "' is outside 1in to 20in (" +
                     number_text(kMinFigureWidthPt) + "pt to " + number_text(kMaxFigureWidthPt) +
                     "pt)");
    return pt;
  }
  throw BadInput(option + ": expected a length such as 85mm, 8.5cm, 3.5in or 241pt, got '" +
                 printable(text) + "'");
}

double parse_font_pt(const std::string& option, const std::string& text) {
  return in_range(option, text, parse_number(option, text), kMinFontPt, kMaxFontPt, " pt");
}

double parse_dpi(const std::string& option, const std::string& text) {
  return in_range(option, text, parse_number(option, text), kMinDpi, kMaxDpi, " dpi");
}

std::optional<PrintSize> parse_print_size(const PrintSizeText& text,
                                          const std::string& width_option,
                                          const std::string& font_option,
                                          const std::string& dpi_option) {
  if (text.width.empty()) {
    for (const auto& [given, option] :
         {std::pair{&text.font, &font_option}, {&text.dpi, &dpi_option}})
      if (!given->empty())
        throw BadInput(*option + ": applies to a figure of a printed size; give " + width_option +
                       " too");
    return std::nullopt;
  }
  PrintSize size;
  size.width_pt = parse_length_pt(width_option, text.width);
  if (!text.font.empty()) size.font_pt = parse_font_pt(font_option, text.font);
  if (!text.dpi.empty()) size.dpi = parse_dpi(dpi_option, text.dpi);
  // A PNG wider than GL draws (and than memory allows at 20 in and 1200 dpi).
  if (size.width_units() > kMaxWidthUnits)
    throw BadInput((text.dpi.empty() ? width_option : dpi_option) + ": " + printable(text.width) +
                   " at " + number_text(size.dpi) + " dpi is " +
                   std::to_string(size.width_units()) + " pixels wide; at most " +
                   std::to_string(kMaxWidthUnits) + " (a lower dpi or a narrower figure)");
  return size;
}

}  // namespace epviz::io
