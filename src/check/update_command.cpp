#include "check/update_command.hpp"

#include "io/shell_quote.hpp"

namespace epviz::check {

std::string update_command(const std::string& job, const std::vector<int>& frames,
                           const std::string& golden_root, const std::string& gl) {
  std::string list;
  for (const int f : frames) {
    if (!list.empty()) list += ',';
    list += std::to_string(f);
  }
  std::string cmd = "epviz check " + io::shell_quote(job) + " --frames " + list;
  if (!golden_root.empty()) cmd += " --golden " + io::shell_quote(golden_root);
  if (!gl.empty()) cmd += " --gl " + io::shell_quote(gl);
  return cmd + " --update";
}

}  // namespace epviz::check
