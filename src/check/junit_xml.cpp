#include "check/junit_xml.hpp"

#include <cstdio>
#include <map>

namespace epviz::check {

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters other than tab and newlines are not allowed in XML 1.0.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r')
          out += '?';
        else
          out += c;
    }
  }
  return out;
}

std::string junit_xml(const std::vector<FrameResult>& results, double seconds) {
  std::vector<std::string> jobs;
  std::map<std::string, std::vector<const FrameResult*>> by_job;
  for (const auto& r : results) {
    if (!by_job.count(r.job)) jobs.push_back(r.job);
    by_job[r.job].push_back(&r);
  }
  std::size_t failures = 0;
  for (const auto& r : results) failures += !r.passed;
  char time[32];
  std::snprintf(time, sizeof time, "%.3f", seconds);

  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += "<testsuites name=\"epviz check\" tests=\"" + std::to_string(results.size()) +
       "\" failures=\"" + std::to_string(failures) + "\" errors=\"0\" time=\"" + time + "\">\n";
  for (const auto& job : jobs) {
    const auto& frames = by_job[job];
    std::size_t job_failures = 0;
    for (const auto* r : frames) job_failures += !r->passed;
    x += "  <testsuite name=\"" + xml_escape(job) + "\" tests=\"" + std::to_string(frames.size()) +
         "\" failures=\"" + std::to_string(job_failures) + "\" errors=\"0\" skipped=\"0\">\n";
    for (const auto* r : frames) {
      x += "    <testcase classname=\"" + xml_escape(job) + "\" name=\"frame " +
           std::to_string(r->frame) + "\"";
      if (r->passed) {
        x +=
            ">\n      <system-out>" + xml_escape(r->message()) + "</system-out>\n    </testcase>\n";
      } else {
        x += ">\n      <failure message=\"" + xml_escape(r->message()) +
             "\" type=\"render regression\">" + xml_escape(r->line()) +
             "</failure>\n    </testcase>\n";
      }
    }
    x += "  </testsuite>\n";
  }
  x += "</testsuites>\n";
  return x;
}

}  // namespace epviz::check
