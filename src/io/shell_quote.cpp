#include "io/shell_quote.hpp"

namespace epviz::io {

std::string shell_quote(const std::string& word) {
  // Spelled out rather than std::isalnum, which depends on the locale.
  static constexpr const char* plain =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./=:,+@%";
  if (!word.empty() && word.find_first_not_of(plain) == std::string::npos) return word;
  std::string q(1, '\'');
  for (const char c : word) {
    if (c == '\'')
      q.append("'\\''");
    else
      q.push_back(c);
  }
  q.push_back('\'');
  return q;
}

}  // namespace epviz::io
