#include "check/html_report.hpp"

#include "check/junit_xml.hpp"

namespace epviz::check {
namespace {

// Element text and attribute values need the same escaping as XML.
std::string esc(const std::string& s) { return xml_escape(s); }

std::string figure(const std::string& caption, const std::string& image) {
  if (image.empty())
    return "<figure><div class=\"none\">none</div><figcaption>" + esc(caption) +
           "</figcaption></figure>";
  return "<figure><a href=\"" + esc(image) + "\"><img src=\"" + esc(image) + "\" alt=\"" +
         esc(caption) + "\"></a><figcaption>" + esc(caption) + "</figcaption></figure>";
}

constexpr const char* kStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; background: #fafafa; color: #222; }
h1 { font-size: 1.4em; } h2 { font-size: 1.1em; margin-top: 2em; }
table { border-collapse: collapse; } td, th { padding: 0.2em 0.8em; border-bottom: 1px solid #ddd; text-align: left; }
.pass { color: #17692c; } .fail { color: #b00020; font-weight: bold; }
.frames { display: flex; gap: 1em; flex-wrap: wrap; }
figure { margin: 0; } figcaption { text-align: center; color: #555; }
img { display: block; min-width: 320px; max-width: 640px; border: 1px solid #999; image-rendering: pixelated; }
.none { width: 160px; height: 120px; border: 1px dashed #999; display: flex; align-items: center; justify-content: center; }
)";

}  // namespace

std::string html_report(const std::vector<FrameResult>& results, const ReportHeader& header) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>epviz "
      "check: " +
      esc(summary(results)) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
  h += "<h1>epviz check: " + esc(summary(results)) + "</h1>\n";
  h +=
      "<p>Tolerance: " + esc(header.tolerance) + "<br>Renderer: " + esc(header.renderer) + "</p>\n";
  h += "<table>\n<tr><th>result</th><th>job</th><th>frame</th><th>measure</th></tr>\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    const std::string cls = r.passed ? "pass" : "fail";
    std::string result = r.passed ? "PASS" : "<a href=\"#f" + std::to_string(i) + "\">FAIL</a>";
    h += "<tr><td class=\"" + cls + "\">" + result + "</td><td>" + esc(r.job) + "</td><td>" +
         std::to_string(r.frame) + "</td><td>" + esc(r.message()) + "</td></tr>\n";
  }
  h += "</table>\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    if (r.passed) continue;
    h += "<section id=\"f" + std::to_string(i) + "\" class=\"failure\">\n<h2>" + esc(r.job) +
         " frame " + std::to_string(r.frame) + "</h2>\n<p class=\"fail\">" + esc(r.message()) +
         "</p>\n<div class=\"frames\">" + figure("golden", r.golden_image) +
         figure("actual", r.actual_image) + figure("diff", r.diff_image) + "</div>\n</section>\n";
  }
  h += "</body>\n</html>\n";
  return h;
}

}  // namespace epviz::check
