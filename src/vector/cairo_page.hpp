#pragma once
// One page of width x height units (a unit per pixel of the matching PNG),
// each unit pt_per_unit points on the page, as an SVG or PDF file's bytes,
// drawn by a callback on a cairo context: the one place that opens,
// finishes and checks cairo's vector surfaces.
#include <functional>
#include <string>

#include <cairo.h>

#include "vector/figure_format.hpp"

namespace epviz::vector {

struct PageInfo {
  int width = 0, height = 0;
  std::string title;  // a PDF's metadata
  std::string name;   // in messages
  // 1: a unit per point (an SVG in px, a browser shows it at the PNG's
  // size); else the page is width x height times this in points, the drawing
  // scaled to it, and an SVG's document unit is the point.
  double pt_per_unit = 1.0;
};

// `format` must be svg or pdf. Throws std::runtime_error naming `page.name`
// when cairo fails.
std::string page_bytes(const PageInfo& page, FigureFormat format,
                       const std::function<void(cairo_t*)>& draw);

}  // namespace epviz::vector
