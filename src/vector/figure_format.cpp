#include "vector/figure_format.hpp"

#include <filesystem>

#include "io/bad_input.hpp"

namespace epviz::vector {

FigureFormat parse_figure_format(const std::string& value, const std::string& option) {
  if (value.empty() || value == "png") return FigureFormat::png;
  if (value == "svg") return FigureFormat::svg;
  if (value == "pdf") return FigureFormat::pdf;
  throw io::BadInput(option + ": '" + value +
                     "' is not a figure format (expected png, svg or pdf)");
}

const char* figure_format_name(FigureFormat format) {
  switch (format) {
    case FigureFormat::svg: return "svg";
    case FigureFormat::pdf: return "pdf";
    case FigureFormat::png: break;
  }
  return "png";
}

std::string figure_file_name(const std::string& file_name, FigureFormat format) {
  return std::filesystem::path(file_name)
      .replace_extension(std::string(".") + figure_format_name(format))
      .string();
}

}  // namespace epviz::vector
