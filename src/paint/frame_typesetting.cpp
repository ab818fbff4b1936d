#include "paint/frame_typesetting.hpp"

#include <cctype>
#include <cstdlib>

#include "paint/figure_common.hpp"

namespace epviz::paint {
namespace {

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// The end of the digits from `i`.
std::size_t digits_end(const std::string& s, std::size_t i) {
  while (i < s.size() && is_digit(s[i])) ++i;
  return i;
}

}  // namespace

std::string print_numbers_in(const std::string& s) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    // A number starts at a digit that does not continue a word or a number.
    const bool starts = is_digit(s[i]) && (i == 0 || !(is_word(s[i - 1]) || s[i - 1] == '.'));
    if (!starts) {
      out += s[i++];
      continue;
    }
    std::size_t end = digits_end(s, i);
    if (end + 1 < s.size() && s[end] == '.' && is_digit(s[end + 1])) end = digits_end(s, end + 1);
    // An exponent: e or E, a sign or none, digits, and then not a word.
    if (end < s.size() && (s[end] == 'e' || s[end] == 'E')) {
      std::size_t k = end + 1;
      if (k < s.size() && (s[k] == '-' || s[k] == '+')) ++k;
      const std::size_t last = digits_end(s, k);
      if (last > k && (last == s.size() || !is_word(s[last]))) {
        const std::string mantissa = s.substr(i, end - i);
        const int exponent = std::atoi(s.substr(end + 1, last - end - 1).c_str());
        out += mantissa == "1" ? power_of_ten(exponent) : mantissa + "×" + power_of_ten(exponent);
        i = last;
        continue;
      }
    }
    out += s.substr(i, end - i);
    i = end;
  }
  return print_minus(out);
}

void typeset_frame_text(scene::Frame& f) {
  f.overlay.title = print_numbers_in(f.overlay.title);
  for (auto& line : f.overlay.lines) line = print_numbers_in(line);
  if (f.comparison)
    for (auto& label : f.comparison->labels) label = print_numbers_in(label);
  f.caption = print_numbers_in(f.caption);
  f.pixel_true_note = print_numbers_in(f.pixel_true_note);
}

}  // namespace epviz::paint
