#include "paint/heat_map_painter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "paint/figure_drawing.hpp"
#include "paint/heat_map_range.hpp"
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

// Dark ink on a light fill, white on a dark one.
glm::vec4 contrasting_ink(const glm::vec4& fill) {
  const bool light = 0.299f * fill.r + 0.587f * fill.g + 0.114f * fill.b > 0.55f;
  return light ? kInk : glm::vec4(1.0f);
}

// The colour bar's range in plotted units: the values' own (whole decades on
// a log scale), or the spec's fixed ends.
struct Range {
  double lo = 0.0, hi = 1.0;
};
Range colour_range(const HeatMapSpec& spec) {
  Span span;
  for (std::size_t i = 0; i < spec.rows.size(); ++i)
    for (std::size_t j = 0; j < spec.columns.size(); ++j)
      if (!undecided(spec, i, j)) span.add(plotted(spec, cell_value(spec, i, j)));
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
  return {span.lo, span.hi};
}

// The height of the colour bar's end triangle for values beyond its range.
// (Its bound's label, level with its tip, keeps a line's distance from the
// tick label at the bar's end.)
int end_triangle(float font_px) { return int(std::ceil(font_px * 1.7f)); }

// The room a map needs around its grid: left of it for the row labels and
// the y title, right of it for the colour bar, its labels and title, and
// under it (besides the column labels) for the x title, the note and `keys`
// key lines. `at_most`: keys counts the key to grey cells wherever a value
// is missing (drawn only on a grid without text, which the room decides).
struct Room {
  float left = 0.0f, right = 0.0f;
  float text_lines = 0.0f;  // the x title under the grid, in pixels (the note's: note_room)
  int keys = 0;
  bool any_missing = false, any_undecided = false;
  OutOfRangeCount beyond;
};
Room room_of(const HeatMapSpec& spec, const ChartFont& font, bool at_most) {
  const float font_px = font.px;
  const float line = font_px * 1.35f;
  Room room;
  for (std::size_t i = 0; i < spec.rows.size(); ++i)
    for (std::size_t j = 0; j < spec.columns.size(); ++j) {
      if (undecided(spec, i, j)) {
        room.any_undecided = true;
        continue;
      }
      const double v = cell_value(spec, i, j);
      room.any_missing |= std::isnan(plotted(spec, v));
      const Beyond b = beyond_range(spec, v);
      room.beyond.above += b == Beyond::above;
      room.beyond.below += b == Beyond::below;
    }
  room.keys = int(room.any_undecided) + int(room.beyond.above > 0) + int(room.beyond.below > 0) +
              int(at_most && room.any_missing);
  room.text_lines = spec.x_label.empty() ? 0.0f : line * 1.2f;
  // A numeric axis's labels are measured at the finest ticks it may get
  // (the most decimals); an axis of names by its names.
  const auto finest_rows = numeric_ticks(spec.row_values, spec.rows.size(), 10);
  float widest_row = font.width(spec.y_label);
  if (finest_rows.empty())
    for (const auto& r : spec.rows) widest_row = std::max(widest_row, font.width(r));
  for (const auto& t : finest_rows) widest_row = std::max(widest_row, font.width(t.label));
  room.left = widest_row + font_px * 1.4f;
  const Range range = colour_range(spec);
  float widest_tick = 0.0f;
  for (const auto& t : axis_ticks(range.lo, range.hi, spec.log_scale, 8))
    widest_tick = std::max(widest_tick, font.width(t.label));
  if (room.beyond.above > 0)
    widest_tick = std::max(widest_tick, font.width(beyond_bound_text(spec, Beyond::above)));
  if (room.beyond.below > 0)
    widest_tick = std::max(widest_tick, font.width(beyond_bound_text(spec, Beyond::below)));
  const float bar_w = font_px * 1.1f;
  room.right =
      std::max(font.width(spec.value_label), bar_w + font_px * 0.5f + widest_tick) + font_px * 2.5f;
  return room;
}

// The note in lines from the grid's left edge `left` to a character short of
// the picture's right edge.
std::vector<std::string> heat_note_lines(const HeatMapSpec& spec, const ChartFont& font, int width,
                                         int left) {
  return wrap_text(spec.note, font, std::max(font.px * 8.0f, float(width - left) - font.px));
}
// The title in lines no wider than the picture, less a character each side.
std::vector<std::string> heat_title_lines(const HeatMapSpec& spec, int width,
                                          const ChartFont& font) {
  return wrap_text(spec.title, font, float(width) - 2.0f * font.px);
}
// The height the note's lines take under the grid (0.4 line above them).
float note_room(std::size_t lines, float line) {
  return lines == 0 ? 0.0f : line * (0.4f + float(lines));
}

}  // namespace

HeatMapLayout heat_map_layout(const HeatMapSpec& spec, int width, int height,
                              const ChartFont& font) {
  const float font_px = font.px;
  const float line = font_px * 1.35f;
  HeatMapLayout l;
  const Range range = colour_range(spec);
  l.lo = range.lo;
  l.hi = range.hi;
  const Room own = room_of(spec, font, false);
  l.beyond = own.beyond;
  Room room = own;
  if (!spec.margin_peers.empty()) {
    // A set of maps: each reserves what the most demanding one needs, every
    // key line that any could draw included, so that all come out alike.
    room = room_of(spec, font, true);
    for (const auto& peer : spec.margin_peers) {
      const Room r = room_of(peer, font, true);
      room.left = std::max(room.left, r.left);
      room.right = std::max(room.right, r.right);
      room.keys = std::max(room.keys, r.keys);
      room.text_lines = std::max(room.text_lines, r.text_lines);
    }
  }
  constexpr int kMostTicks = 10;
  const auto finest_rows = numeric_ticks(spec.row_values, spec.rows.size(), kMostTicks);
  const auto finest_columns = numeric_ticks(spec.column_values, spec.columns.size(), kMostTicks);
  float widest_column = 0.0f;
  if (finest_columns.empty())
    for (const auto& c : spec.columns) widest_column = std::max(widest_column, font.width(c));
  float widest_column_tick = 0.0f;
  for (const auto& t : finest_columns)
    widest_column_tick = std::max(widest_column_tick, font.width(t.label));
  float widest_value = 0.0f;
  for (const auto& row : spec.values)
    for (double v : row)
      if (!std::isnan(plotted(spec, v)))
        widest_value = std::max(widest_value, font.width(heat_value_text(v)));
  if (own.any_missing) widest_value = std::max(widest_value, font.width(spec.missing));
  if (own.any_undecided) widest_value = std::max(widest_value, font.width(spec.undecided_label));
  const float bar_w = font_px * 1.1f;
  const int left = int(std::ceil(room.left));
  // The note wrapped to the width; a set of maps reserves its longest note's lines.
  l.note_lines = heat_note_lines(spec, font, width, left);
  std::size_t note_count = l.note_lines.size();
  for (const auto& peer : spec.margin_peers)
    note_count = std::max(note_count, heat_note_lines(peer, font, width, left).size());
  room.text_lines += note_room(note_count, line);
  // A line for the title (more where it wraps), and one for the y label.
  // A set of maps reserves its longest title's lines.
  std::size_t title_lines = std::max<std::size_t>(1, heat_title_lines(spec, width, font).size());
  for (const auto& peer : spec.margin_peers)
    title_lines = std::max(title_lines, heat_title_lines(peer, width, font).size());
  const int top = int(std::ceil(font_px * 0.8f + line * (float(title_lines) + 0.3f) + line * 1.2f));
  const int grid_w = std::max(16, width - left - int(std::ceil(room.right)));
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
  // The keys to hatched cells and to cells beyond the range are always
  // there: a cell's text may not say it all.
  l.undecided_key = own.any_undecided;
  auto place = [&](bool key) {
    // A set of maps reserves its most demanding member's lines (room.keys
    // counts the key to grey cells whether or not it is drawn).
    const int keys = spec.margin_peers.empty() ? int(key) + own.keys : room.keys;
    const float under = font_px * 0.6f + line * (l.staggered_columns ? 2.0f : 1.0f) +
                        room.text_lines + line * 1.4f * float(keys) + font_px * 0.6f;
    const int bottom = int(std::ceil(under));
    const float cell_h =
        std::min(cell_h_max, float(std::max(16, height - top - bottom)) / float(rows));
    l.natural_height = top + int(std::ceil(cell_h_max * float(rows))) + bottom;
    // All values as text or none: a grid where only some cells say their value
    // would read as if the others had none.
    l.value_text = widest_value + font_px * 0.4f <= cell_w && font_px * 1.15f <= cell_h;
    l.missing_key = own.any_missing && !l.value_text;
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
  // The colour bar beside the grid, shortened at an end that carries a
  // triangle for values beyond it.
  // (On a grid of a row or two the triangles take at most a quarter of it each.)
  const int end = std::min(end_triangle(font_px), grid_h / 4);
  const int cut_top = l.beyond.above > 0 ? end : 0, cut_bottom = l.beyond.below > 0 ? end : 0;
  l.colour_bar = {left + grid_w + int(font_px * 1.5f), top + cut_top, int(bar_w),
                  std::max(8, grid_h - cut_top - cut_bottom)};
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

namespace {
// A value at the colour bar's end on `side` (in values, not plotted units).
double end_value(const HeatMapSpec& spec, const HeatMapLayout& l, Beyond side) {
  const double v = side == Beyond::above ? l.hi : l.lo;
  return spec.log_scale ? std::pow(10.0, v) : v;
}
}  // namespace

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
  const auto title = heat_title_lines(spec, options.width, font);
  for (std::size_t i = 0; i < title.size(); ++i)
    list.add_text(label({float(options.width) * 0.5f, font_px * 0.6f + line * float(i)}, title[i],
                        TextAnchor::top));
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
        // A value beyond the range: a triangle across most of the cell.
        if (const Beyond side = beyond_range(spec, v); side != Beyond::no)
          add_beyond_triangle(list, (a + b) * 0.5f, std::min(b.x - a.x, b.y - a.y) * 0.6f, side,
                              contrasting_ink(fill));
        continue;
      }
      const glm::vec4 ink = contrasting_ink(fill);
      // A value beyond the range: a triangle in the cell's top right corner, clear of its text.
      if (const Beyond side = beyond_range(spec, v); side != Beyond::no) {
        const float size = std::clamp(std::min<float>(c.width, c.height) * 0.28f, 5.0f, font_px);
        add_beyond_triangle(list, {b.x - size * 0.5f - 2.0f, a.y + size * 0.5f + 2.0f}, size, side,
                            ink);
      }
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
  if (!l.note_lines.empty()) {
    for (std::size_t i = 0; i < l.note_lines.size(); ++i)
      list.add_text(label({float(l.grid.x), under + line * (0.4f + float(i))}, l.note_lines[i],
                          TextAnchor::top_left, quiet_ink));
    under += note_room(l.note_lines.size(), line);
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
    under += line * 1.4f;
  }
  // The keys to cells beyond the range: a swatch of the end colour with its triangle.
  for (const Beyond side : {Beyond::above, Beyond::below}) {
    const std::size_t n = side == Beyond::above ? l.beyond.above : l.beyond.below;
    if (n == 0) continue;
    const glm::vec2 a{float(l.grid.x), under + line * 0.4f};
    const glm::vec2 b{a.x + font_px * 1.2f, a.y + font_px * 0.9f};
    const glm::vec4 end = heat_map_colour(spec, l, end_value(spec, l, side)).value_or(missing);
    list.add_rect(a, b, end);
    add_beyond_triangle(list, (a + b) * 0.5f, font_px * 0.6f, side, contrasting_ink(end));
    list.add_text(label({b.x + font_px * 0.5f, (a.y + b.y) * 0.5f}, beyond_key_text(spec, side, n),
                        TextAnchor::left, quiet_ink));
    under += line * 1.4f;
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
  // An end triangle for values beyond the bar, in its end colour, with its bound.
  for (const Beyond side : {Beyond::above, Beyond::below}) {
    if ((side == Beyond::above ? l.beyond.above : l.beyond.below) == 0) continue;
    const bool above = side == Beyond::above;
    const float tip = above ? float(l.grid.y) : float(l.grid.y + l.grid.height);
    const float base = above ? float(b.y) : float(b.y + b.height);
    const glm::vec4 end = heat_map_colour(spec, l, end_value(spec, l, side)).value_or(missing);
    const float x0 = float(b.x), x1 = float(b.x + b.width), xm = (x0 + x1) * 0.5f;
    const std::vector<render::ColouredVertex> triangle{
        {{x0, base, 0}, end}, {{x1, base, 0}, end}, {{xm, tip, 0}, end}};
    list.add_triangles(triangle);
    const std::vector<glm::vec3> edge{{x0, base, 0}, {xm, tip, 0}, {x1, base, 0}};
    list.add_polyline(edge, kFrame, 1.0f, false);
    // The bound level with the tip, a line from the bar's end tick at the base.
    list.add_text(
        label({x1 + font_px * 0.45f, tip}, beyond_bound_text(spec, side), TextAnchor::left));
  }
  const int max_labels = std::clamp(int(float(b.height) / (font_px * 1.6f)), 2, 8);
  for (const auto& t : axis_ticks(l.lo, l.hi, spec.log_scale, max_labels)) {
    if (t.label.empty()) continue;
    const float y = float(b.y + b.height) - float((t.at - l.lo) / (l.hi - l.lo)) * float(b.height);
    list.add_line({float(b.x + b.width), y, 0}, {float(b.x + b.width) + font_px * 0.3f, y, 0},
                  kFrame, 1.0f);
    list.add_text(label({float(b.x + b.width) + font_px * 0.45f, y}, t.label, TextAnchor::left));
  }
  list.add_text(label({float(b.x), float(l.grid.y) - font_px * 0.9f}, spec.value_label,
                      TextAnchor::bottom_left));
  drawing.layers.push_back({std::move(list), std::nullopt});
  return drawing;
}

}  // namespace epviz::paint
