#pragma once
// Several figures written into one folder in one format: PNG painted by the
// GL painter (a context is opened only then), SVG or PDF drawn with cairo (no
// GL needed). Each file is the figure's file name with the format's extension.
#include <filesystem>
#include <string>
#include <vector>

#include "chart/chart_spec.hpp"
#include "paint/figure_common.hpp"
#include "vector/figure_format.hpp"

namespace epviz::vector {

// `gl`: the --gl option's value, as render::GlChoice reads it. Returns the
// paths written, in the figures' order; no figures: nothing is opened or
// written. Throws render::GlUnavailable when PNG cannot be drawn here.
std::vector<std::filesystem::path> write_figures(const std::vector<chart::Figure>& figures,
                                                 const std::filesystem::path& dir,
                                                 FigureFormat format, const std::string& gl,
                                                 const paint::ChartOptions& options = {});

}  // namespace epviz::vector
