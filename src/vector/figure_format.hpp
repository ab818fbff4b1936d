#pragma once
// The file formats a figure can be written in: PNG (the GL painter's pixels),
// SVG or PDF (cairo's vectors, this module), chosen with --format.
#include <string>

namespace epviz::vector {

enum class FigureFormat { png, svg, pdf };

// "png", "svg" or "pdf" ("" is png); anything else throws io::BadInput naming
// `option` and the allowed values.
FigureFormat parse_figure_format(const std::string& value, const std::string& option = "--format");
// "png", "svg" or "pdf".
const char* figure_format_name(FigureFormat format);
// `file_name` with the format's extension in place of its own ("drift.png" -> "drift.svg").
std::string figure_file_name(const std::string& file_name, FigureFormat format);

}  // namespace epviz::vector
