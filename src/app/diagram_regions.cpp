#include "app/diagram_regions.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace epviz::app {
namespace {

// A straight piece of a drawn curve, between two of its points.
struct CurvePiece {
  double e0, k0, e1, k1;
  int run = -1;  // which attained part of which curve (-1: a bridge)
  double e_low() const { return std::min(e0, e1); }
  double e_high() const { return std::max(e0, e1); }
  // The line through the piece at energy e (extrapolated past its ends).
  double k_at(double e) const { return k0 + (k1 - k0) * (e - e0) / (e1 - e0); }
};

std::vector<CurvePiece> curve_pieces(const physics::BifurcationDiagram& d) {
  std::vector<CurvePiece> pieces;
  int run = 0;
  for (const auto& c : d.curves) {
    if (c.isolated) continue;
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
      const auto& p = c.points[i];
      const auto& q = c.points[i + 1];
      if (std::isfinite(p.energy) && std::isfinite(q.energy) && std::isfinite(p.integral) &&
          std::isfinite(q.integral))
        pieces.push_back({p.energy, p.integral, q.energy, q.integral, run});
      else
        ++run;
    }
    ++run;
  }
  return pieces;
}

// The point of the piece nearest (x, y), and its distance, in the chart's spans.
std::pair<physics::ValuePoint, double> nearest_on_piece(const CurvePiece& p, double x, double y,
                                                        double dx, double dy) {
  const double ax = p.e0 / dx, ay = p.k0 / dy, vx = p.e1 / dx - ax, vy = p.k1 / dy - ay;
  const double len2 = vx * vx + vy * vy;
  const double t =
      len2 > 0 ? std::clamp(((x / dx - ax) * vx + (y / dy - ay) * vy) / len2, 0.0, 1.0) : 0.0;
  const physics::ValuePoint q{p.e0 + t * (p.e1 - p.e0), p.k0 + t * (p.k1 - p.k0)};
  return {q, std::hypot((x - q.energy) / dx, (y - q.integral) / dy)};
}

// An attained part of a curve begins at the first of the energies the
// search tried where it is attained, up to one step past where it meets
// another curve (at C0 = 3 the s > 0 branch rises from class II at h = 3.25):
// the gap left would join the parts on either side. So each end of a part
// that lies within two of its last piece's lengths of another part is
// joined to it by a straight bridge; ends at the chart's left or right edge
// (within `margin` of it) are left open.
void bridge_ends(std::vector<CurvePiece>& pieces, double e_min, double e_max, double margin,
                 double dx, double dy) {
  std::vector<CurvePiece> bridges;
  const std::size_t n = pieces.size();
  for (std::size_t i = 0; i < n; ++i) {
    const CurvePiece& p = pieces[i];
    const double len = std::hypot((p.e1 - p.e0) / dx, (p.k1 - p.k0) / dy);
    std::vector<physics::ValuePoint> ends;
    if (i == 0 || pieces[i - 1].run != p.run) ends.push_back({p.e0, p.k0});
    if (i + 1 == n || pieces[i + 1].run != p.run) ends.push_back({p.e1, p.k1});
    for (const auto& end : ends) {
      if (end.energy - e_min < margin || e_max - end.energy < margin) continue;
      physics::ValuePoint best{};
      double distance = INFINITY;
      for (std::size_t j = 0; j < n; ++j) {
        if (pieces[j].run == p.run) continue;
        const auto [q, d] = nearest_on_piece(pieces[j], end.energy, end.integral, dx, dy);
        if (d < distance) best = q, distance = d;
      }
      if (distance <= 2 * len && distance > 0)
        bridges.push_back({end.energy, end.integral, best.energy, best.integral, -1});
    }
  }
  pieces.insert(pieces.end(), bridges.begin(), bridges.end());
}

// One interval of the integral's axis on one energy, between two curves
// (or below the lowest, above the highest: an infinite end).
struct AxisInterval {
  int column = 0;
  double low = -INFINITY, high = INFINITY;
  std::size_t samples = 0;
  double sampled_low = INFINITY, sampled_high = -INFINITY;
};

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Whether some k in [low, high] is covered by none of `blocked` (each a
// closed range), with a gap wider than `eps`.
bool has_free_gap(double low, double high, std::vector<std::pair<double, double>> blocked,
                  double eps) {
  std::sort(blocked.begin(), blocked.end());
  double cursor = low;
  for (const auto& [a, b] : blocked) {
    if (a >= high) break;
    if (a - cursor > eps) return true;
    cursor = std::max(cursor, b);
    if (cursor >= high) return false;
  }
  return high - cursor > eps;
}

// Whether the segment from (x0, y0) to (x1, y1) meets the piece (touching
// counts), in the chart's spans so that the orientation tests are scaled.
bool segment_meets(const CurvePiece& p, double x0, double y0, double x1, double y1, double dx,
                   double dy) {
  const double ax = p.e0 / dx, ay = p.k0 / dy, bx = p.e1 / dx, by = p.k1 / dy;
  x0 /= dx, x1 /= dx, y0 /= dy, y1 /= dy;
  const auto side = [](double px, double py, double qx, double qy, double rx, double ry) {
    const double c = (qx - px) * (ry - py) - (qy - py) * (rx - px);
    return (c > 0) - (c < 0);
  };
  const int d1 = side(x0, y0, x1, y1, ax, ay), d2 = side(x0, y0, x1, y1, bx, by);
  const int d3 = side(ax, ay, bx, by, x0, y0), d4 = side(ax, ay, bx, by, x1, y1);
  return d1 * d2 <= 0 && d3 * d4 <= 0;
}

// The distance from (x, y) to the piece, both in the chart's spans.
double piece_distance(const CurvePiece& p, double x, double y, double dx, double dy) {
  const double ax = p.e0 / dx, ay = p.k0 / dy, bx = p.e1 / dx, by = p.k1 / dy;
  const double vx = bx - ax, vy = by - ay, len2 = vx * vx + vy * vy;
  double t = len2 > 0 ? ((x - ax) * vx + (y - ay) * vy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(x - (ax + t * vx), y - (ay + t * vy));
}

std::string region_label(std::size_t i) {
  if (i < 26) return std::string(1, char('A' + i));
  return "R" + std::to_string(i + 1);
}

}  // namespace

std::vector<DiagramRegion> diagram_regions(const physics::BifurcationDiagram& d, int columns) {
  const double e0 = d.energy_min, e1 = d.energy_max;
  if (!(e1 > e0) || columns < 2 || d.sampled.empty()) return {};
  const double de = (e1 - e0) / columns;
  std::vector<CurvePiece> pieces = curve_pieces(d);

  double k_min = INFINITY, k_max = -INFINITY;
  std::vector<std::vector<physics::ValuePoint>> in_column(columns);
  for (const auto& s : d.sampled) {
    if (!std::isfinite(s.energy) || !std::isfinite(s.integral)) continue;
    const int j = std::clamp(int(std::floor((s.energy - e0) / de)), 0, columns - 1);
    in_column[j].push_back(s);
    k_min = std::min(k_min, s.integral), k_max = std::max(k_max, s.integral);
  }
  const double dy = k_max > k_min ? k_max - k_min : 1.0, dx = e1 - e0;
  const double eps = 1e-9 * dy;
  bridge_ends(pieces, e0, e1, 1.5 * de, dx, dy);

  // Every column's intervals, sampled or not (a thin part of a region may
  // hold no sample on some energies and still join its neighbours); first[j]
  // indexes column j's first.
  std::vector<AxisInterval> nodes;
  std::vector<std::size_t> first(columns + 1, 0);
  for (int j = 0; j < columns; ++j) {
    first[j] = nodes.size();
    const double e = e0 + (j + 0.5) * de;
    std::vector<std::pair<double, std::size_t>> cuts;  // (k, piece) where a curve crosses e
    for (std::size_t p = 0; p < pieces.size(); ++p)
      if (pieces[p].e_low() <= e && e < pieces[p].e_high()) cuts.push_back({pieces[p].k_at(e), p});
    std::sort(cuts.begin(), cuts.end());
    std::vector<AxisInterval> axis(cuts.size() + 1);
    for (std::size_t i = 0; i < axis.size(); ++i) {
      axis[i].column = j;
      if (i > 0) axis[i].low = cuts[i - 1].first;
      if (i < cuts.size()) axis[i].high = cuts[i].first;
    }
    // A sample is placed against the curves at its own energy, not the
    // column's, so that a steep boundary curve does not leave a sliver of
    // samples on its far side.
    for (const auto& s : in_column[j]) {
      std::size_t below = 0;
      for (const auto& c : cuts) below += pieces[c.second].k_at(s.energy) < s.integral;
      auto& a = axis[below];
      ++a.samples;
      a.sampled_low = std::min(a.sampled_low, s.integral);
      a.sampled_high = std::max(a.sampled_high, s.integral);
    }
    nodes.insert(nodes.end(), axis.begin(), axis.end());
  }
  first[columns] = nodes.size();

  std::vector<std::size_t> parent(nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (int j = 0; j + 1 < columns; ++j) {
    const double a = e0 + (j + 0.5) * de, b = a + de;
    // The integrals the curves take between the two energies.
    std::vector<std::pair<double, double>> blocked;
    std::vector<std::size_t> in_strip;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const CurvePiece& p = pieces[i];
      if (p.e_high() < a || p.e_low() > b) continue;
      in_strip.push_back(i);
      if (p.e_high() == p.e_low()) {
        blocked.push_back({std::min(p.k0, p.k1), std::max(p.k0, p.k1)});
        continue;
      }
      const double ka = p.k_at(std::max(a, p.e_low())), kb = p.k_at(std::min(b, p.e_high()));
      blocked.push_back({std::min(ka, kb), std::max(ka, kb)});
    }
    for (std::size_t u = first[j]; u < first[j + 1]; ++u)
      for (std::size_t v = first[j + 1]; v < first[j + 2]; ++v) {
        const double low = std::max(nodes[u].low, nodes[v].low);
        const double high = std::min(nodes[u].high, nodes[v].high);
        // Two paths that cross no curve: a level one through the common
        // range, or, for a band between two curves that climbs by more than
        // its width from one energy to the next, the one from middle to middle.
        bool joined = high > low && has_free_gap(low, high, blocked, eps);
        const double mu = 0.5 * (nodes[u].low + nodes[u].high);
        const double mv = 0.5 * (nodes[v].low + nodes[v].high);
        if (!joined && std::isfinite(mu) && std::isfinite(mv))
          joined = std::none_of(in_strip.begin(), in_strip.end(), [&](std::size_t i) {
            return segment_meets(pieces[i], a, mu, b, mv, dx, dy);
          });
        if (joined) parent[find_root(parent, u)] = find_root(parent, v);
      }
  }

  struct Found {
    DiagramRegion region;
    bool seen = false;
  };
  std::vector<Found> found(nodes.size());
  for (std::size_t u = 0; u < nodes.size(); ++u) {
    const AxisInterval& n = nodes[u];
    Found& f = found[find_root(parent, u)];
    f.region.samples += n.samples;
    // The interval's drawn extent: its curves, or its samples where it is open.
    const double low = std::isfinite(n.low) ? n.low : n.sampled_low;
    const double high = std::isfinite(n.high) ? n.high : n.sampled_high;
    if (!(high > low)) continue;
    const double e = e0 + (n.column + 0.5) * de, k = 0.5 * (low + high);
    double clearance = std::min({(k - low) / dy, (high - k) / dy, (e - e0) / dx, (e1 - e) / dx});
    for (const auto& p : pieces) {
      if (clearance <= (f.seen ? f.region.clearance : 0.0)) break;  // cannot beat the best
      clearance = std::min(clearance, piece_distance(p, e / dx, k / dy, dx, dy));
    }
    if (!f.seen || clearance > f.region.clearance) {
      f.region.point = {e, k};
      f.region.clearance = clearance;
      f.seen = true;
    }
  }
  std::vector<DiagramRegion> regions;
  for (const auto& f : found)
    if (f.seen && f.region.samples >= kMinRegionSamples) regions.push_back(f.region);
  std::sort(regions.begin(), regions.end(), [](const DiagramRegion& x, const DiagramRegion& y) {
    if (x.point.energy != y.point.energy) return x.point.energy < y.point.energy;
    return x.point.integral < y.point.integral;
  });
  for (std::size_t i = 0; i < regions.size(); ++i) regions[i].label = region_label(i);
  return regions;
}

}  // namespace epviz::app
