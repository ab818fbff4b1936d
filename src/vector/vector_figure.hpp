#pragma once
// Figures as vector files: a chart, heat map or table (chart/chart_spec.hpp)
// drawn with cairo into an SVG or PDF with the same layout as the PNG the GL
// painter makes of it (paint/figure_drawing.hpp lays out both), a pixel of
// the PNG options.page_pt_per_unit points of the page (1, or 72/dpi for a
// figure of a printed size). A PDF holds its labels as text (a reader can
// select and search them, the font embedded); cairo's SVG holds them as glyph
// outlines, which look the same everywhere.
//
//   vector::write_vector_figure("drift.pdf", figure, vector::FigureFormat::pdf);
#include <filesystem>
#include <string>
#include <vector>

#include "chart/chart_spec.hpp"
#include "paint/figure_common.hpp"
#include "vector/figure_format.hpp"

namespace epviz::vector {

// The file's bytes; `format` must be svg or pdf (png throws std::invalid_argument).
std::string vector_figure_bytes(const chart::Figure& figure, FigureFormat format,
                                const paint::ChartOptions& options = {});
// Writes them to `path` atomically.
void write_vector_figure(const std::filesystem::path& path, const chart::Figure& figure,
                         FigureFormat format, const paint::ChartOptions& options = {});

// Several figures side by side in one file (paint/figure_panels.hpp), each
// laid out at the options' size, `gap` pixels apart, in rows of `columns`
// (0: all in one row); written atomically.
void write_vector_panels(const std::filesystem::path& path,
                         const std::vector<chart::Figure>& panels, FigureFormat format,
                         const paint::ChartOptions& options, int gap, int columns = 0);

}  // namespace epviz::vector
