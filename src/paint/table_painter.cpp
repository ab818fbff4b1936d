#include "paint/table_painter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "paint/figure_drawing.hpp"
#include "render/draw_list.hpp"

namespace epviz::paint {
namespace {

using render::DrawList;
using render::TextAnchor;

}  // namespace

FigureDrawing draw_table(const TableSpec& spec, const ChartOptions& options,
                         const ChartFont& font) {
  const float font_px = font.px;
  const float line = font_px * 1.5f;
  std::size_t columns = spec.header.size();
  for (const auto& r : spec.rows) columns = std::max(columns, r.size());
  auto cell = [](const std::vector<std::string>& row, std::size_t c) {
    return c < row.size() ? row[c] : std::string();
  };

  // Column widths from the longest cell, scaled down together if the table is too wide.
  std::vector<float> widths(columns, 0.0f);
  for (std::size_t c = 0; c < columns; ++c) {
    widths[c] = font.width(cell(spec.header, c));
    for (const auto& r : spec.rows) widths[c] = std::max(widths[c], font.width(cell(r, c)));
    widths[c] += font_px * 1.2f;
  }
  const float margin = font_px * 1.5f;
  float total = 0.0f;
  for (float w : widths) total += w;
  const float avail = float(options.width) - 2.0f * margin;
  if (total > avail && total > 0.0f)
    for (float& w : widths) w *= avail / total;
  total = std::min(total, avail);

  DrawList list;
  const float left = std::max(margin, (float(options.width) - total) * 0.5f);
  float y = font_px * 0.8f;
  if (!spec.title.empty()) {
    list.add_text(label({float(options.width) * 0.5f, y}, spec.title, TextAnchor::top));
    y += line * 1.3f;
  }
  const float rule_heavy = std::max(1.5f, font_px * 0.1f);
  list.add_line({left, y, 0}, {left + total, y, 0}, kInk, rule_heavy);
  auto write_row = [&](const std::vector<std::string>& row, float top, const glm::vec4& colour) {
    float x = left;
    for (std::size_t c = 0; c < columns; ++c) {
      list.add_text(
          label({x + font_px * 0.4f, top + line * 0.5f}, cell(row, c), TextAnchor::left, colour));
      x += widths[c];
    }
  };
  if (!spec.header.empty()) {
    write_row(spec.header, y, kInk);
    y += line;
    list.add_line({left, y, 0}, {left + total, y, 0}, kInk, 1.0f);
  }
  const float bottom_limit = float(options.height) - font_px;
  std::size_t shown = 0;
  for (const auto& r : spec.rows) {
    if (y + line > bottom_limit - line) break;
    if (shown % 2 == 1)
      list.add_rect({left, y}, {left + total, y + line}, {0.0f, 0.0f, 0.0f, 0.04f});
    write_row(r, y, kInk);
    y += line;
    ++shown;
  }
  list.add_line({left, y, 0}, {left + total, y, 0}, kInk, rule_heavy);
  if (shown < spec.rows.size()) {
    char more[64];
    std::snprintf(more, sizeof more, "(%zu more rows not shown)", spec.rows.size() - shown);
    list.add_text(
        label({left, y + font_px * 0.4f}, more, TextAnchor::top_left, {0.4f, 0.4f, 0.4f, 1.0f}));
  }
  FigureDrawing drawing{options.width, options.height, {}};
  drawing.layers.push_back({std::move(list), std::nullopt});
  return drawing;
}

}  // namespace epviz::paint
