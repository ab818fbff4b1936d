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

// The columns' widths and each row's lines at a picture's width.
struct TableColumns {
  std::size_t columns = 0;
  float pad = 0.0f;     // inside a column, besides its text
  float margin = 0.0f;  // left and right of the table
  std::vector<float> widths;
  float total = 0.0f;
  static std::string cell(const std::vector<std::string>& row, std::size_t c) {
    return c < row.size() ? row[c] : std::string();
  }
  // A cell's lines: its text wrapped to its column (less the padding).
  std::vector<std::string> lines_of(const std::vector<std::string>& row, std::size_t c,
                                    const ChartFont& font) const {
    return wrap_text(cell(row, c), font, widths[c] - pad);
  }
  // A row is as many lines tall as its tallest cell.
  std::size_t row_lines(const std::vector<std::string>& row, const ChartFont& font) const {
    std::size_t n = 1;
    for (std::size_t c = 0; c < columns; ++c) n = std::max(n, lines_of(row, c, font).size());
    return n;
  }
};

// The widest piece of `text` that wrap_text keeps on one line when it can:
// a word, or a part of one after a break it prefers ("_", "-", ...).
float widest_piece(const std::string& text, const ChartFont& font) {
  float widest = 0.0f;
  std::string piece;
  for (char ch : text) {
    if (ch == ' ') {
      widest = std::max(widest, font.width(piece));
      piece.clear();
      continue;
    }
    piece += ch;
    if (is_soft_break(ch)) {
      widest = std::max(widest, font.width(piece));
      piece.clear();
    }
  }
  return std::max(widest, font.width(piece));
}

// Column widths from the longest cell. A table too wide for the picture (a
// narrow figure at a printed size) closes up its padding and margins, keeps
// each column as wide as its widest word, shares the rest of the width in
// proportion to what each column lacks, and wraps its cells onto more lines;
// where even the words do not fit, every column narrows alike and words break.
TableColumns table_columns(const TableSpec& spec, const ChartOptions& options,
                           const ChartFont& font) {
  const float font_px = font.px;
  TableColumns t;
  t.columns = spec.header.size();
  for (const auto& r : spec.rows) t.columns = std::max(t.columns, r.size());
  std::vector<float> natural(t.columns, 0.0f), least(t.columns, 0.0f);
  float natural_sum = 0.0f, least_sum = 0.0f;
  for (std::size_t c = 0; c < t.columns; ++c) {
    for (const auto* row : {&spec.header}) {
      natural[c] = font.width(TableColumns::cell(*row, c));
      least[c] = widest_piece(TableColumns::cell(*row, c), font);
    }
    for (const auto& r : spec.rows) {
      natural[c] = std::max(natural[c], font.width(TableColumns::cell(r, c)));
      least[c] = std::max(least[c], widest_piece(TableColumns::cell(r, c), font));
    }
    natural_sum += natural[c];
    least_sum += least[c];
  }
  const float columns = float(std::max<std::size_t>(1, t.columns));
  t.pad = font_px * 1.2f;
  t.margin = font_px * 1.5f;
  std::vector<float> text = natural;
  if (natural_sum + t.pad * columns > float(options.width) - 2.0f * t.margin) {
    t.pad = font_px * 0.6f;
    t.margin = font_px * 0.5f;
    const float avail = std::max(0.0f, float(options.width) - 2.0f * t.margin - t.pad * columns);
    for (std::size_t c = 0; c < t.columns; ++c)
      text[c] = least_sum <= avail ? least[c] + (natural[c] - least[c]) * (avail - least_sum) /
                                                    std::max(natural_sum - least_sum, 1e-3f)
                                   : least[c] * avail / std::max(least_sum, 1e-3f);
  }
  for (float w : text) {
    t.widths.push_back(w + t.pad);
    t.total += w + t.pad;
  }
  return t;
}

// The title's lines, centred on the picture.
std::vector<std::string> table_title_lines(const TableSpec& spec, const ChartOptions& options,
                                           const ChartFont& font, float margin) {
  return wrap_text(spec.title, font, float(options.width) - 2.0f * margin);
}

}  // namespace

int table_height(const TableSpec& spec, const ChartOptions& options, const ChartFont& font) {
  const float line = font.px * 1.5f;
  const TableColumns t = table_columns(spec, options, font);
  // The title, the header and the rows as drawn, with the margins, the note
  // of rows left out and room to spare as a table has always had (8 lines
  // for one line each of title and header: see draw_figure).
  std::size_t lines =
      std::max<std::size_t>(1, table_title_lines(spec, options, font, t.margin).size()) + 6;
  lines += t.row_lines(spec.header, font);
  for (const auto& r : spec.rows) lines += t.row_lines(r, font);
  return int(std::ceil(line * float(lines)));
}

FigureDrawing draw_table(const TableSpec& spec, const ChartOptions& options,
                         const ChartFont& font) {
  const float font_px = font.px;
  const float line = font_px * 1.5f;
  const TableColumns t = table_columns(spec, options, font);
  const std::size_t columns = t.columns;
  const std::vector<float>& widths = t.widths;
  const float total = t.total;
  const float margin = t.margin;
  auto lines_of = [&](const std::vector<std::string>& row, std::size_t c) {
    return t.lines_of(row, c, font);
  };
  auto row_lines = [&](const std::vector<std::string>& row) { return t.row_lines(row, font); };

  DrawList list;
  const float left = std::max(margin, (float(options.width) - total) * 0.5f);
  float y = font_px * 0.8f;
  for (const auto& title_line : table_title_lines(spec, options, font, margin)) {
    list.add_text(label({float(options.width) * 0.5f, y}, title_line, TextAnchor::top));
    y += line;
  }
  if (!spec.title.empty()) y += line * 0.3f;
  const float rule_heavy = std::max(1.5f * options.thin_line, font_px * 0.1f);
  list.add_line({left, y, 0}, {left + total, y, 0}, kInk, rule_heavy);
  // A wrapped row is as many lines tall as its tallest cell, its cells' first lines aligned.
  auto write_row = [&](const std::vector<std::string>& row, float top, const glm::vec4& colour) {
    float x = left;
    for (std::size_t c = 0; c < columns; ++c) {
      const auto text = lines_of(row, c);
      for (std::size_t k = 0; k < text.size(); ++k)
        list.add_text(label({x + font_px * 0.4f, top + line * (0.5f + float(k))}, text[k],
                            TextAnchor::left, colour));
      x += widths[c];
    }
  };
  if (!spec.header.empty()) {
    write_row(spec.header, y, kInk);
    y += line * float(row_lines(spec.header));
    list.add_line({left, y, 0}, {left + total, y, 0}, kInk, options.thin_line);
  }
  const float bottom_limit = float(options.height) - font_px;
  std::size_t shown = 0;
  for (const auto& r : spec.rows) {
    const float h = line * float(row_lines(r));
    if (y + h > bottom_limit - line) break;
    if (shown % 2 == 1) list.add_rect({left, y}, {left + total, y + h}, {0.0f, 0.0f, 0.0f, 0.04f});
    write_row(r, y, kInk);
    y += h;
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
