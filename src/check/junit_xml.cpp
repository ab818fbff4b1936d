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

namespace {

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", seconds);
  return text;
}

// The frame's message, then one attachment line per report image.
std::string system_out(const FrameResult& r, const std::filesystem::path& report_dir) {
  std::string out = xml_escape(r.message());
  for (const auto* image : {&r.golden_image, &r.actual_image, &r.diff_image})
    if (!image->empty())
      out += "\n[[ATTACHMENT|" + xml_escape((report_dir / *image).generic_string()) + "]]";
  return "      <system-out>" + out + "</system-out>\n";
}

}  // namespace

std::string junit_xml(const std::vector<FrameResult>& results, double seconds,
                      const std::filesystem::path& report_dir) {
  std::vector<std::string> jobs;
  std::map<std::string, std::vector<const FrameResult*>> by_job;
  for (const auto& r : results) {
    if (!by_job.count(r.job)) jobs.push_back(r.job);
    by_job[r.job].push_back(&r);
  }
  std::size_t failures = 0;
  for (const auto& r : results) failures += !r.passed;

  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += "<testsuites name=\"epviz check\" tests=\"" + std::to_string(results.size()) +
       "\" failures=\"" + std::to_string(failures) + "\" errors=\"0\" time=\"" +
       seconds_text(seconds) + "\">\n";
  for (const auto& job : jobs) {
    const auto& frames = by_job[job];
    std::size_t job_failures = 0;
    double job_seconds = 0.0;
    for (const auto* r : frames) {
      job_failures += !r->passed;
      job_seconds += r->seconds;
    }
    x += "  <testsuite name=\"" + xml_escape(job) + "\" tests=\"" + std::to_string(frames.size()) +
         "\" failures=\"" + std::to_string(job_failures) + "\" errors=\"0\" skipped=\"0\" time=\"" +
         seconds_text(job_seconds) + "\">\n";
    for (const auto* r : frames) {
      x += "    <testcase classname=\"" + xml_escape(job) + "\" name=\"frame " +
           std::to_string(r->frame) + "\" time=\"" + seconds_text(r->seconds) + "\">\n";
      if (!r->passed)
        x += "      <failure message=\"" + xml_escape(r->message()) +
             "\" type=\"render regression\">" + xml_escape(r->line()) + "</failure>\n";
      x += system_out(*r, report_dir) + "    </testcase>\n";
    }
    x += "  </testsuite>\n";
  }
  x += "</testsuites>\n";
  return x;
}

}  // namespace epviz::check
