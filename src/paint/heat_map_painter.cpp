#include "paint/heat_map_painter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "paint/figure_drawing.hpp"
#include "render/colour_map.hpp"
#include "render/draw_list.hpp"

namespace epviz::paint {
namespace {

using render::DrawList;
using render::TextAnchor;
using render::Viewport;

const render::ColourMap& heat_map() {
  static const render::ColourMap map = render::ColourMap::time();
  return map;
}

double plotted(const HeatMapSpec& spec, double v) {
  if (!std::isfinite(v)) return kNaN;
  if (spec.log_scale) return v > 0.0 ? std::log10(v) : kNaN;
  return v;
}

// The value of a cell; NaN where the spec's values stop short of its rows or columns.
double cell_value(const HeatMapSpec& spec, std::size_t row, std::size_t column) {
  if (row >= spec.values.size() || column >= spec.values[row].size()) return kNaN;
  return spec.values[row][column];
}

bool undecided(const HeatMapSpec& spec, std::size_t row, std::size_t column) {
  return row < spec.undecided.size() && column < spec.undecided[row].size() &&
         spec.undecided[row][column];
}

// Diagonal stripes (lower left to upper right) over the rectangle a..b.
void add_hatch(DrawList& list, glm::vec2 a, glm::vec2 b, const glm::vec4& colour, float spacing) {
  for (float s = a.x + a.y + spacing * 0.5f; s < b.x + b.y; s += spacing) {
    const float x0 = std::max(a.x, s - b.y), x1 = std::min(b.x, s - a.y);
    if (x1 > x0) list.add_line({x0, s - x0, 0}, {x1, s - x1, 0}, colour, 1.0f);
  }
}

// The ticks of a numeric axis, if `values` makes it one (one per cell) of
// enough cells to be read as a continuous axis; a few cells are each named
// by their own value, which is exact where round ticks between them would
// suggest values no run had.
constexpr std::size_t kFewestCellsForTicks = 8;
std::vector<GridTick> numeric_ticks(const std::vector<double>& values, std::size_t cells,
                                    int max_labels) {
  return values.size() == cells && cells >= kFewestCellsForTicks ? grid_ticks(values, max_labels)
                                                                 : std::vector<GridTick>{};
}

// Drops the ticks whose label would reach into the one before it: `extent`
// is a label's size along the axis, `cell` a cell's.
void keep_apart(std::vector<GridTick>& ticks, float cell,
                const std::function<float(const GridTick&)>& extent) {
  std::vector<GridTick> kept;
  for (auto& t : ticks) {
    if (!kept.empty()) {
      const float gap = float(t.position - kept.back().position) * cell;
      if (gap < 0.5f * (extent(t) + extent(kept.back()))) continue;
    }
    kept.push_back(std::move(t));
  }
  ticks = std::move(kept);
}

std::string heat_value_text(double v) { return print_number(v, 3); }

}  // namespace

HeatMapLayout heat_map_layout(const HeatMapSpec& spec, int width, int height,
                              const ChartFont& font) {
  const float font_px = font.px;
  HeatMapLayout l;
  Span span;
  bool any_missing = false, any_undecided = false;
  for (std::size_t i = 0; i < spec.rows.size(); ++i)
    for (std::size_t j = 0; j < spec.columns.size(); ++j) {
      if (undecided(spec, i, j)) {
        any_undecided = true;
        continue;
      }
      const double v = plotted(spec, cell_value(spec, i, j));
      span.add(v);
      any_missing |= std::isnan(v);
    }
  finish_span(span, spec.log_scale);
  if (!spec.log_scale && !span.empty()) {
    // finish_span pads a linear range; a colour scale wants the values' own ends.
    const double pad = (span.hi - span.lo) / 1.08 * 0.04;
    span.lo += pad;
    span.hi -= pad;
  }
  // A fixed range is taken as given (not rounded to decades): maps that share
  // it colour the same value alike.
  if (const double v = plotted(spec, spec.range_min); std::isfinite(v)) span.lo = v;
  if (const double v = plotted(spec, spec.range_max); std::isfinite(v)) span.hi = v;
  if (!(span.hi > span.lo)) span.hi = span.lo + 1.0;
  l.lo = span.lo;
  l.hi = span.hi;

  const float line = font_px * 1.35f;
  // A numeric axis's labels are measured at the finest ticks it may get
  // (the most decimals); an axis of names by its names.
  constexpr int kMostTicks = 10;
  const auto finest_rows = numeric_ticks(spec.row_values, spec.rows.size(), kMostTicks);
  const auto finest_columns = numeric_ticks(spec.column_values, spec.columns.size(), kMostTicks);
  float widest_row = font.width(spec.y_label);
  if (finest_rows.empty())
    for (const auto& r : spec.rows) widest_row = std::max(widest_row, font.width(r));
  for (const auto& t : finest_rows) widest_row = std::max(widest_row, font.width(t.label));
  float widest_column = 0.0f;
  if (finest_columns.empty())
    for (const auto& c : spec.columns) widest_column = std::max(widest_column, font.width(c));
  float widest_column_tick = 0.0f;
  for (const auto& t : finest_columns)
    widest_column_tick = std::max(widest_column_tick, font.width(t.label));
  float widest_tick = 0.0f;
  for (const auto& t : axis_ticks(l.lo, l.hi, spec.log_scale, 8))
    widest_tick = std::max(widest_tick, font.width(t.label));
  float widest_value = 0.0f;
  for (const auto& row : spec.values)
    for (double v : row)
      if (!std::isnan(plotted(spec, v)))
        widest_value = std::max(widest_value, font.width(heat_value_text(v)));
  if (any_missing) widest_value = std::max(widest_value, font.width(spec.missing));
  if (any_undecided) widest_value = std::max(widest_value, font.width(spec.undecided_label));
  const float bar_w = font_px * 1.1f;
  const float right =
      std::max(font.width(spec.value_label), bar_w + font_px * 0.5f + widest_tick) + font_px * 2.5f;
  const int left = int(std::ceil(widest_row + font_px * 1.4f));
  const int top = int(std::ceil(font_px * 0.8f + line * 1.3f + line * 1.2f));
  const int grid_w = std::max(16, width - left - int(std::ceil(right)));
  const std::size_t columns = std::max<std::size_t>(1, spec.columns.size());
  const std::size_t rows = std::max<std::size_t>(1, spec.rows.size());
  const float cell_w = float(grid_w) / float(columns);
  // Column labels side by side where they fit a cell, on two lines where they
  // fit two, else every k-th one (with a gap of most of a character).
  const float column_gap = font_px * 0.5f;
  if (widest_column + column_gap * 0.5f > cell_w) {
    if (widest_column + column_gap <= 2.0f * cell_w)
      l.staggered_columns = true;
    else
      l.column_stride = std::size_t(std::ceil((widest_column + column_gap) / cell_w));
  }
  // The lines under the grid: column labels, the x axis title, the note, the
  // key to grey cells when they carry no text (known only once the rows'
  // height is: hence a second pass with that line when the first finds it needed).
  const float cell_h_max = font_px * 2.6f;
  // The key to hatched cells is always there: a cell's text may not say it all.
  l.undecided_key = any_undecided;
  auto place = [&](bool key) {
    const int keys = int(key) + int(l.undecided_key);
    const float under = font_px * 0.6f + line * (l.staggered_columns ? 2.0f : 1.0f) +
                        (spec.x_label.empty() ? 0.0f : line * 1.2f) +
                        (spec.note.empty() ? 0.0f : line * 1.4f) + line * 1.4f * float(keys) +
                        font_px * 0.6f;
    const int bottom = int(std::ceil(under));
    const float cell_h =
        std::min(cell_h_max, float(std::max(16, height - top - bottom)) / float(rows));
    l.natural_height = top + int(std::ceil(cell_h_max * float(rows))) + bottom;
    // All values as text or none: a grid where only some cells say their value
    // would read as if the others had none.
    l.value_text = widest_value + font_px * 0.4f <= cell_w && font_px * 1.15f <= cell_h;
    l.missing_key = any_missing && !l.value_text;
    l.row_stride = std::size_t(std::ceil(line / std::max(cell_h, 1.0f) - 1e-4f));
    return cell_h;
  };
  float cell_h = place(false);
  if (l.missing_key) cell_h = place(true);
  const int grid_h = int(std::floor(cell_h * float(rows)));
  l.grid = {left, top, grid_w, grid_h};
  l.cells.assign(spec.rows.size(), {});
  for (std::size_t i = 0; i < spec.rows.size(); ++i)
    for (std::size_t j = 0; j < spec.columns.size(); ++j) {
      const int x0 = left + int(std::round(cell_w * float(j))),
                x1 = left + int(std::round(cell_w * float(j + 1)));
      const int y0 = top + int(std::round(cell_h * float(i))),
                y1 = top + int(std::round(cell_h * float(i + 1)));
      l.cells[i].push_back({x0, y0, x1 - x0, y1 - y0});
    }
  l.colour_bar = {left + grid_w + int(font_px * 1.5f), top, int(bar_w), grid_h};
  if (!finest_columns.empty()) {
    const float per_label = widest_column_tick + font_px * 2.0f;
    l.column_ticks = numeric_ticks(spec.column_values, spec.columns.size(),
                                   std::clamp(int(float(grid_w) / per_label), 2, kMostTicks));
    keep_apart(l.column_ticks, cell_w,
               [&](const GridTick& t) { return font.width(t.label) + font_px; });
  }
  if (!finest_rows.empty()) {
    l.row_ticks = numeric_ticks(spec.row_values, spec.rows.size(),
                                std::clamp(int(float(grid_h) / (line * 2.0f)), 2, kMostTicks));
    keep_apart(l.row_ticks, cell_h, [&](const GridTick&) { return line; });
  }
  return l;
}

std::optional<glm::vec4> heat_map_colour(const HeatMapSpec& spec, const HeatMapLayout& l,
                                         double value) {
  const double v = plotted(spec, value);
  if (std::isnan(v)) return std::nullopt;
  double t = l.hi > l.lo ? (v - l.lo) / (l.hi - l.lo) : 0.5;
  t = std::clamp(t, 0.0, 1.0);
  if (!spec.larger_is_better) t = 1.0 - t;
  return heat_map()(float(t), 1.0f);
}

FigureDrawing draw_heat_map(const HeatMapSpec& spec, const ChartOptions& options,
                            const ChartFont& font, bool fit_grid) {
  const float font_px = font.px;
  const float line = font_px * 1.35f;
  HeatMapLayout l = heat_map_layout(spec, options.width, options.height, font);
  FigureDrawing drawing{options.width, options.height, {}};
  if (fit_grid && l.natural_height < options.height) {
    drawing.height = l.natural_height;
    l = heat_map_layout(spec, options.width, l.natural_height, font);
  }
  DrawList list;
  if (!spec.title.empty())
    list.add_text(
        label({float(options.width) * 0.5f, font_px * 0.6f}, spec.title, TextAnchor::top));
  const glm::vec4 missing{0.88f, 0.88f, 0.89f, 1.0f};
  const glm::vec4 hatch{0.62f, 0.62f, 0.64f, 1.0f};
  const glm::vec4 quiet_ink{0.35f, 0.35f, 0.38f, 1.0f};
  // Undecided cells: paper white under darker stripes than a missing cell's
  // diagonal, so that neither reads as the other nor as a colour of the map.
  const glm::vec4 undecided_fill{0.97f, 0.97f, 0.96f, 1.0f};
  const float hatch_spacing = std::max(5.0f, font_px * 0.5f);
  const float tick = font_px * 0.3f;
  const float grid_bottom = float(l.grid.y + l.grid.height);
  for (std::size_t i = 0; i < l.cells.size(); ++i) {
    const Viewport& first = l.cells[i].empty() ? l.grid : l.cells[i][0];
    const float row_y = float(first.y) + first.height * 0.5f;
    if (l.row_ticks.empty() && i % l.row_stride == 0) {
      list.add_text(
          label({float(l.grid.x) - font_px * 0.5f, row_y}, spec.rows[i], TextAnchor::right));
      if (l.row_stride > 1)  // which row a thinned label names
        list.add_line({float(l.grid.x) - tick, row_y, 0}, {float(l.grid.x), row_y, 0}, kFrame,
                      1.0f);
    }
    for (std::size_t j = 0; j < l.cells[i].size(); ++j) {
      const Viewport& c = l.cells[i][j];
      if (undecided(spec, i, j)) {
        const float gap = l.value_text ? 1.0f : 0.0f;
        const glm::vec2 a{float(c.x) + gap, float(c.y) + gap};
        const glm::vec2 b{float(c.x + c.width) - gap, float(c.y + c.height) - gap};
        list.add_rect(a, b, undecided_fill);
        add_hatch(list, a, b, hatch, hatch_spacing);
        if (l.value_text) {  // on a box of paper, so that the stripes do not cross it
          auto text = label({float(c.x) + c.width * 0.5f, float(c.y) + c.height * 0.5f},
                            spec.undecided_label, TextAnchor::centre);
          text.background = undecided_fill;
          list.add_text(std::move(text));
        }
        continue;
      }
      const double v = cell_value(spec, i, j);
      const auto colour = heat_map_colour(spec, l, v);
      const glm::vec4 fill = colour.value_or(missing);
      // One pixel of paper between cells that hold text (a table of values);
      // colour-only cells touch, so that a large grid reads as one picture.
      const float gap = l.value_text ? 1.0f : 0.0f;
      const glm::vec2 a{float(c.x) + gap, float(c.y) + gap};
      const glm::vec2 b{float(c.x + c.width) - gap, float(c.y + c.height) - gap};
      list.add_rect(a, b, fill);
      if (!l.value_text) {
        // No text to say so: a diagonal marks the grey as no value rather than a colour.
        if (!colour) list.add_line({a.x, b.y, 0}, {b.x, a.y, 0}, hatch, 1.0f);
        continue;
      }
      const bool light = 0.299f * fill.r + 0.587f * fill.g + 0.114f * fill.b > 0.55f;
      const glm::vec4 ink = light ? kInk : glm::vec4(1.0f);
      list.add_text(label({float(c.x) + c.width * 0.5f, float(c.y) + c.height * 0.5f},
                          colour ? heat_value_text(v) : spec.missing, TextAnchor::centre,
                          colour ? ink : quiet_ink));
    }
  }
  // A numeric axis: a tick and its round value where it falls between the cells.
  const float cell_w = float(l.grid.width) / float(std::max<std::size_t>(1, spec.columns.size()));
  const float cell_h = float(l.grid.height) / float(std::max<std::size_t>(1, spec.rows.size()));
  for (const auto& t : l.row_ticks) {
    const float y = float(l.grid.y) + float(t.position + 0.5) * cell_h;
    list.add_line({float(l.grid.x) - tick, y, 0}, {float(l.grid.x), y, 0}, kFrame, 1.0f);
    list.add_text(label({float(l.grid.x) - font_px * 0.5f, y}, t.label, TextAnchor::right));
  }
  for (const auto& t : l.column_ticks) {
    const float x = float(l.grid.x) + float(t.position + 0.5) * cell_w;
    list.add_line({x, grid_bottom, 0}, {x, grid_bottom + tick, 0}, kFrame, 1.0f);
    list.add_text(label({x, grid_bottom + font_px * 0.5f}, t.label, TextAnchor::top));
  }
  // Column labels under the grid, on two lines where they are wider than a
  // cell, every k-th one (with a tick) where even two lines would overlap.
  for (std::size_t j = 0; l.column_ticks.empty() && j < spec.columns.size(); j += l.column_stride) {
    const Viewport& c = l.cells.empty() ? l.grid : l.cells[0][j];
    const float x = float(c.x) + c.width * 0.5f;
    const float y =
        grid_bottom + font_px * 0.5f + (l.staggered_columns && j % 2 == 1 ? line : 0.0f);
    list.add_text(label({x, y}, spec.columns[j], TextAnchor::top));
    if (l.column_stride > 1)
      list.add_line({x, grid_bottom, 0}, {x, grid_bottom + tick, 0}, kFrame, 1.0f);
  }
  float under = grid_bottom + font_px * 0.5f + line * (l.staggered_columns ? 2.0f : 1.0f);
  if (!spec.x_label.empty()) {
    list.add_text(label({float(l.grid.x) + float(l.grid.width) * 0.5f, under + line * 0.2f},
                        spec.x_label, TextAnchor::top));
    under += line * 1.2f;
  }
  if (!spec.y_label.empty())
    list.add_text(label({float(l.grid.x) - font_px * 0.5f, float(l.grid.y) - font_px * 0.9f},
                        spec.y_label, TextAnchor::bottom_right));
  if (!spec.note.empty()) {
    list.add_text(
        label({float(l.grid.x), under + line * 0.4f}, spec.note, TextAnchor::top_left, quiet_ink));
    under += line * 1.4f;
  }
  if (l.missing_key) {
    const glm::vec2 a{float(l.grid.x), under + line * 0.4f};
    const glm::vec2 b{a.x + font_px * 1.2f, a.y + font_px * 0.9f};
    list.add_rect(a, b, missing);
    list.add_line({a.x, b.y, 0}, {b.x, a.y, 0}, hatch, 1.0f);
    list.add_text(label({b.x + font_px * 0.5f, (a.y + b.y) * 0.5f}, spec.missing, TextAnchor::left,
                        quiet_ink));
    under += line * 1.4f;
  }
  if (l.undecided_key) {
    const glm::vec2 a{float(l.grid.x), under + line * 0.4f};
    const glm::vec2 b{a.x + font_px * 1.2f, a.y + font_px * 0.9f};
    list.add_rect(a, b, undecided_fill);
    add_hatch(list, a, b, hatch, hatch_spacing * 0.6f);
    list.add_text(label({b.x + font_px * 0.5f, (a.y + b.y) * 0.5f}, spec.undecided_label,
                        TextAnchor::left, quiet_ink));
  }
  // The colour bar: 64 bands, low values at the bottom. Each band reaches
  // down to the bar's bottom and the higher ones are drawn first, so that no
  // edge between two bands lies on paper: a vector file's rasteriser would
  // show one as a pale hairline.
  const Viewport& b = l.colour_bar;
  std::vector<render::ColouredVertex> strip;
  constexpr int kSteps = 64;
  for (int k = kSteps - 1; k >= 0; --k) {
    const float y1 = float(b.y + b.height);
    const float y0 = float(b.y + b.height) - float(b.height) * float(k + 1) / kSteps;
    const double v = l.lo + (l.hi - l.lo) * (double(k) + 0.5) / kSteps;
    const double value = spec.log_scale ? std::pow(10.0, v) : v;
    const glm::vec4 c = heat_map_colour(spec, l, value).value_or(missing);
    for (const glm::vec2 p :
         {glm::vec2(b.x, y0), glm::vec2(b.x + b.width, y0), glm::vec2(b.x + b.width, y1),
          glm::vec2(b.x, y0), glm::vec2(b.x + b.width, y1), glm::vec2(b.x, y1)})
      strip.push_back({glm::vec3(p, 0), c});
  }
  list.add_triangles(strip);
  const std::vector<glm::vec3> bar_frame{{float(b.x), float(b.y), 0},
                                         {float(b.x + b.width), float(b.y), 0},
                                         {float(b.x + b.width), float(b.y + b.height), 0},
                                         {float(b.x), float(b.y + b.height), 0}};
  list.add_polyline(bar_frame, kFrame, 1.0f, true);
  const int max_labels = std::clamp(int(float(b.height) / (font_px * 1.6f)), 2, 8);
  for (const auto& t : axis_ticks(l.lo, l.hi, spec.log_scale, max_labels)) {
    if (t.label.empty()) continue;
    const float y = float(b.y + b.height) - float((t.at - l.lo) / (l.hi - l.lo)) * float(b.height);
    list.add_line({float(b.x + b.width), y, 0}, {float(b.x + b.width) + font_px * 0.3f, y, 0},
                  kFrame, 1.0f);
    list.add_text(label({float(b.x + b.width) + font_px * 0.45f, y}, t.label, TextAnchor::left));
  }
  list.add_text(
      label({float(b.x), float(b.y) - font_px * 0.9f}, spec.value_label, TextAnchor::bottom_left));
  drawing.layers.push_back({std::move(list), std::nullopt});
  return drawing;
}

}  // namespace epviz::paint
