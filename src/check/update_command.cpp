#include "check/update_command.hpp"

#include <algorithm>
#include <cctype>
#include <string_view>

namespace epviz::check {
namespace {

// Single-quotes a shell word unless it is plainly safe.
std::string shell_word(const std::string& s) {
  const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string_view("_./:=,@%+-").find(c) != std::string_view::npos;
  });
  if (plain) return s;
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string update_command(const std::string& job, const std::vector<int>& frames,
                           const std::string& golden_root, const std::string& gl) {
  std::string list;
  for (const int f : frames) {
    if (!list.empty()) list += ',';
    list += std::to_string(f);
  }
  std::string cmd = "epviz check " + shell_word(job) + " --frames " + list;
  if (!golden_root.empty()) cmd += " --golden " + shell_word(golden_root);
  if (!gl.empty()) cmd += " --gl " + shell_word(gl);
  return cmd + " --update";
}

}  // namespace epviz::check
