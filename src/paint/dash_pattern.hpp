#pragma once
// Dashed lines for a toolkit that draws only solid ones: a pattern of on and
// off lengths in pixels, laid along a polyline by its length on screen, cut
// into the pieces to draw. Plain geometry, no GL.
#include <cstddef>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "scene/frame.hpp"

namespace epviz::paint {

// A place on a polyline: on the segment from vertex `segment` to the next, at
// `fraction` (0..1) of its length.
struct PolylineAt {
  std::size_t segment = 0;
  float fraction = 0.0f;
};
struct DashSpan {
  PolylineAt from, to;
};

// The spans a dash pattern draws along a polyline whose vertices lie at
// `pixels` on screen: on for pattern[0] pixels, off for pattern[1], on for
// pattern[2], ... (an even number of entries); an empty pattern (solid) gives
// the whole line.
std::vector<DashSpan> dash_spans(std::span<const glm::vec2> pixels, std::span<const float> pattern);

// The pattern of a run's line style, in pixels, for a line `width` pixels wide.
// `open`: the looser pattern of the line after the run's pixel-true time
// (a solid line becomes dashed, the others' gaps grow by 70 %).
std::vector<float> dash_pattern(scene::LineStyle style, float width, bool open);

// The vertices of one span of `vertices`; `lerp(a, b, s)` interpolates two of them.
template <class V, class Lerp>
std::vector<V> span_vertices(std::span<const V> vertices, const DashSpan& s, Lerp lerp) {
  // A span that starts at a segment's end or ends at its start names the
  // vertex there once, not twice.
  PolylineAt a = s.from, b = s.to;
  if (a.fraction >= 1.0f && a.segment < b.segment) a = {a.segment + 1, 0.0f};
  if (b.fraction <= 0.0f && b.segment > a.segment) b = {b.segment - 1, 1.0f};
  std::vector<V> out;
  out.push_back(lerp(vertices[a.segment], vertices[a.segment + 1], a.fraction));
  for (std::size_t i = a.segment + 1; i <= b.segment; ++i) out.push_back(vertices[i]);
  out.push_back(lerp(vertices[b.segment], vertices[b.segment + 1], b.fraction));
  return out;
}

}  // namespace epviz::paint
