#pragma once
// What poppler reads back from a PDF, for tests of figures at a printed size:
// the page's width in points (pdfinfo) and each word's box in points
// (pdftotext -bbox, whose XHTML has a <word xMin= yMin= xMax= yMax=> per
// word, y down from the page's top), and which words' boxes overlap. These
// are the PDF reader's own facts, independent of how epviz laid the page out.
//
//   if (!test::have_poppler()) GTEST_SKIP() << "no pdftotext/pdfinfo";
//   for (const auto& w : test::pdf_words(pdf)) EXPECT_GE(w.height(), 6.0) << w.text;
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <regex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace epviz::test {

struct PdfWord {
  std::string text;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // points; y0 the top, y1 the bottom
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

// Whether pdftotext and pdfinfo (poppler-utils) are installed.
inline bool have_poppler() {
  return std::system("command -v pdftotext >/dev/null && command -v pdfinfo >/dev/null") == 0;
}

// The standard output of `command` (throws when it cannot be run or fails).
inline std::string command_output(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), ::pclose);
  if (!pipe) throw std::runtime_error("cannot run: " + command);
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe.get())) > 0;) out.append(buf, n);
  if (::pclose(pipe.release()) != 0) throw std::runtime_error("failed: " + command);
  return out;
}

inline std::string shell_word(const std::filesystem::path& p) {
  std::string q = "'";
  for (char c : p.string()) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The XML escapes pdftotext writes in a word's text, undone.
inline std::string xml_unescaped(std::string s) {
  for (const auto& [from, to] : {std::pair{"&lt;", "<"},
                                 {"&gt;", ">"},
                                 {"&quot;", "\""},
                                 {"&apos;", "'"},
                                 {"&#39;", "'"},
                                 {"&amp;", "&"}}) {
    for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += 1)
      s.replace(at, std::string(from).size(), to);
  }
  return s;
}

// Every word of every page of `pdf`, in pdftotext's reading order.
inline std::vector<PdfWord> pdf_words(const std::filesystem::path& pdf) {
  const std::string xhtml = command_output("pdftotext -bbox " + shell_word(pdf) + " -");
  // <word xMin="9.36" yMin="35.14" xMax="18.10" yMax="43.13">10</word>
  const std::string number = "\"([-0-9.]+)\"";
  static const std::regex word("<word xMin=" + number + " yMin=" + number + " xMax=" + number +
                               " yMax=" + number + ">([^<]*)</word>");
  std::vector<PdfWord> words;
  for (std::sregex_iterator it(xhtml.begin(), xhtml.end(), word), end; it != end; ++it) {
    const auto& m = *it;
    words.push_back({xml_unescaped(m[5].str()), std::stod(m[1].str()), std::stod(m[2].str()),
                     std::stod(m[3].str()), std::stod(m[4].str())});
  }
  return words;
}

// The first page's width and height in points, as pdfinfo reports them
// ("Page size:       240.94 x 180.7 pts").
inline std::pair<double, double> pdf_page_size_pt(const std::filesystem::path& pdf) {
  const std::string info = command_output("pdfinfo " + shell_word(pdf));
  static const std::regex size(R"(Page size:\s+([0-9.]+) x ([0-9.]+) pts)");
  std::smatch m;
  if (!std::regex_search(info, m, size)) throw std::runtime_error("no page size in: " + info);
  return {std::stod(m[1].str()), std::stod(m[2].str())};
}
inline double pdf_page_width_pt(const std::filesystem::path& pdf) {
  return pdf_page_size_pt(pdf).first;
}

// The area two words' boxes share.
inline double shared_area(const PdfWord& a, const PdfWord& b) {
  const double w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0);
  const double h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return w > 0 && h > 0 ? w * h : 0.0;
}

// The pairs of words whose boxes share more than `share` of the smaller box:
// text drawn over text.
inline std::vector<std::pair<PdfWord, PdfWord>> overlapping_words(const std::vector<PdfWord>& words,
                                                                  double share = 0.1) {
  std::vector<std::pair<PdfWord, PdfWord>> pairs;
  for (std::size_t i = 0; i < words.size(); ++i)
    for (std::size_t j = i + 1; j < words.size(); ++j) {
      const double smaller =
          std::min(words[i].width() * words[i].height(), words[j].width() * words[j].height());
      if (smaller > 0 && shared_area(words[i], words[j]) > share * smaller)
        pairs.emplace_back(words[i], words[j]);
    }
  return pairs;
}

}  // namespace epviz::test
