#include "check/what_changed.hpp"

#include "io/printable.hpp"

namespace epviz::check {
namespace {

std::string quoted(const std::string& text) {
  std::string s = "'";
  s += io::printable(text, 120);
  s += '\'';
  return s;
}

std::string font_text(const std::string& file, const std::string& hash) {
  std::string s = quoted(file);
  if (!hash.empty()) {
    s += " (";
    s += io::printable(hash, 40);
    s += ')';
  }
  return s;
}

std::string difference(const char* part, const std::string& then, const std::string& now) {
  std::string s = part;
  s += ' ';
  s += then;
  s += " in golden.json, ";
  s += now;
  s += " now";
  return s;
}

std::string joined(const std::vector<std::string>& phrases) {
  std::string s;
  for (const auto& p : phrases) {
    if (!s.empty()) s += "; ";
    s += p;
  }
  return s;
}

}  // namespace

std::vector<std::string> environment_differences(const GoldenRecord& record,
                                                 const RenderEnvironment& now) {
  std::vector<std::string> out;
  if (record.gl_renderer != now.gl_renderer)
    out.push_back(difference("GL renderer", quoted(record.gl_renderer), quoted(now.gl_renderer)));
  if (record.gl_version != now.gl_version)
    out.push_back(difference("GL version", quoted(record.gl_version), quoted(now.gl_version)));
  // The same font may sit at another path: its bytes decide.
  const bool font_recorded = !record.font_file.empty();
  const bool same_font = record.font_hash.empty() && now.font_hash.empty()
                             ? record.font_file == now.font_file
                             : record.font_hash == now.font_hash;
  if (font_recorded && !same_font)
    out.push_back(difference("font", font_text(record.font_file, record.font_hash),
                             font_text(now.font_file, now.font_hash)));
  return out;
}

std::string failure_cause(const std::optional<GoldenRecord>& record, const std::string& job_hash,
                          const RenderEnvironment& now, const std::string& update_command) {
  if (!record)
    return "no golden.json beside the goldens, so whether the job or the rendering changed is "
           "unknown";
  if (record->job_hash.empty())
    return "golden.json records no job_hash, so whether the job or the rendering changed is "
           "unknown";
  if (record->job_hash != job_hash)
    return "job changed since goldens: update or revert (update: " + update_command + ")";
  const auto differences = environment_differences(*record, now);
  if (differences.empty())
    return "rendering changed, the job did not (same GL renderer, GL version and font as the "
           "goldens)";
  return "rendering changed, the job did not; differs from the goldens: " + joined(differences);
}

}  // namespace epviz::check
