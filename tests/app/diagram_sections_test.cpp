// `epviz diagram --sections`: the regions it finds are the connected parts of
// the level's image that the closed-form critical curves (docs/math.md §2.6)
// cut it into, counted here on a grid from those formulas alone; each region
// has a section whose every crossing is on its region's level, with C1, C0
// and K computed here from the state; bad values are refused before any work.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace epviz {
namespace {

using test::run_epviz;
using test::TempDir;

constexpr double kArea = 0.5;        // ℓ
constexpr double kEnergyMax = 2.75;  // given on the command line: the grid's right edge

std::vector<std::vector<std::string>> csv_rows(const std::filesystem::path& file,
                                               std::string& header) {
  std::ifstream in(file);
  std::getline(in, header);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

// The preset Kovalevskaya top's closed-form curves at area ℓ (ε = 1): the
// parametric curve h = s + ℓ²/(4s²), k = 1 − ℓ²/(2s) + ℓ⁴/(16s⁴) and class II.
double parametric_energy(double s) { return s + kArea * kArea / (4 * s * s); }
double parametric_integral(double s) {
  const double l2 = kArea * kArea;
  return 1 - l2 / (2 * s) + l2 * l2 / (16 * s * s * s * s);
}
double class_two(double h) { return (h - kArea * kArea / 2) * (h - kArea * kArea / 2); }

// The s with parametric_energy(s) = h on [a, b], where h(s) is monotone.
double solve_s(double h, double a, double b) {
  const bool rising = parametric_energy(b) > parametric_energy(a);
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    ((parametric_energy(m) < h) == rising ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// The s < 0 branch at energy h: h rises from −∞ to +∞ as s runs over (−∞, 0).
double upper_boundary(double h) { return parametric_integral(solve_s(h, -1e3, -1e-6)); }

// The closed forms' values at one energy.
struct CurvesAt {
  double h, top, low_arm = NAN, high_arm = NAN;
};
CurvesAt curves_at(double h) {
  CurvesAt c{h, upper_boundary(h)};
  const double cusp = std::cbrt(kArea * kArea / 2);  // s* = (ℓ²/2)^(1/3)
  if (h > parametric_energy(cusp)) {
    const double a = parametric_integral(solve_s(h, 1e-6, cusp));  // s in (0, s*)
    const double b = parametric_integral(solve_s(h, cusp, 1e3));   // s > s*
    c.low_arm = std::min(a, b), c.high_arm = std::max(a, b);
  }
  return c;
}

// Where (h, k) lies against the curves: outside the image (−1), or a code
// that is the same for two points exactly when no curve lies between them
// along a path that keeps to one side of each: the side of class II, and
// whether it is inside the cusped wedge between the two arms of the s > 0
// branch (which exist from the cusp on).
int classify(const CurvesAt& c, double k) {
  // The image (docs/diagram.md): under the s < 0 branch, above class II up
  // to h = ℓ²/2 and above k = 0 from there on.
  const bool above_bottom = c.h < kArea * kArea / 2 ? k > class_two(c.h) : k > 0;
  if (!(k < c.top) || !above_bottom) return -1;
  const bool wedge = k > c.low_arm && k < c.high_arm;  // false without arms (NaN)
  return 2 * int(k > class_two(c.h)) + int(wedge);
}
int classify(double h, double k) { return classify(curves_at(h), k); }

// The connected parts of the image on a grid of the plane: nodes of one
// code joined to their eight neighbours of the same code. Parts of fewer
// than 0.05% of the image's nodes are the grid's aliasing at a region's tip
// and are not counted. Returns the part of every node (−1: none).
struct GridParts {
  double h0, dh, k0, dk;
  int nh, nk;
  std::vector<int> part;
  int count = 0;
  int at(double h, double k) const {
    const int i = int(std::lround((h - h0) / dh)), j = int(std::lround((k - k0) / dk));
    if (i < 0 || i >= nh || j < 0 || j >= nk) return -1;
    return part[std::size_t(i) * nk + j];
  }
};

GridParts closed_form_parts(double h_min) {
  GridParts g{h_min, 0, 0.0, 0, 900, 900, {}, 0};
  g.dh = (kEnergyMax - h_min) / (g.nh - 1);
  g.dk = upper_boundary(kEnergyMax) / (g.nk - 1);
  std::vector<int> code(std::size_t(g.nh) * g.nk);
  for (int i = 0; i < g.nh; ++i) {
    const CurvesAt column = curves_at(h_min + i * g.dh);
    for (int j = 0; j < g.nk; ++j) code[std::size_t(i) * g.nk + j] = classify(column, j * g.dk);
  }
  g.part.assign(code.size(), -1);
  std::vector<int> sizes;
  std::size_t image = 0;
  for (std::size_t n = 0; n < code.size(); ++n) {
    if (code[n] < 0 || g.part[n] >= 0) continue;
    const int id = int(sizes.size());
    sizes.push_back(0);
    std::vector<std::size_t> stack{n};
    g.part[n] = id;
    while (!stack.empty()) {
      const std::size_t m = stack.back();
      stack.pop_back();
      ++sizes[id];
      const int i = int(m / g.nk), j = int(m % g.nk);
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          const int a = i + di, b = j + dj;
          if (a < 0 || a >= g.nh || b < 0 || b >= g.nk) continue;
          const std::size_t q = std::size_t(a) * g.nk + b;
          if (g.part[q] < 0 && code[q] == code[n]) g.part[q] = id, stack.push_back(q);
        }
    }
    image += std::size_t(sizes[id]);
  }
  // Renumber the counted parts 0, 1, ...; the others become −1.
  std::vector<int> renumber(sizes.size(), -1);
  for (std::size_t id = 0; id < sizes.size(); ++id)
    if (double(sizes[id]) >= 5e-4 * double(image)) renumber[id] = g.count++;
  for (auto& p : g.part)
    if (p >= 0) p = renumber[std::size_t(p)];
  return g;
}

TEST(DiagramSections, KovalevskayaRegionsAreTheClosedFormCurvesPartsAndEachSectionKeepsItsLevel) {
  // The image's left corner: where the s < 0 branch meets class II.
  double lo = -5, hi = kArea * kArea / 2;
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (lo + hi);
    (upper_boundary(m) > class_two(m) ? hi : lo) = m;
  }
  const GridParts parts = closed_form_parts(hi);
  // The count can fail: with class II alone the plane has fewer parts.
  EXPECT_GE(parts.count, 2);

  TempDir dir;
  const auto out = dir / "kov";
  const auto r = run_epviz(
      "diagram --case kovalevskaya --area 0.5 --energy-max 2.75 --sections 3 "
      "--section-crossings 30 --out " +
          out.string(),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string header;
  const auto regions = csv_rows(out / "regions.csv", header);
  EXPECT_EQ(header, "region,energy,integral,clearance,samples");
  EXPECT_EQ(int(regions.size()), parts.count) << r.out;
  EXPECT_NE(r.out.find(std::to_string(parts.count) + " regions"), std::string::npos) << r.out;

  // Each region's point lies in a closed-form part of its own.
  std::set<int> hit;
  for (const auto& row : regions) {
    ASSERT_EQ(row.size(), 5u);
    const std::string label = row[0];
    const double h = std::stod(row[1]), k = std::stod(row[2]);
    SCOPED_TRACE("region " + label);
    const int part = parts.at(h, k);
    EXPECT_GE(part, 0) << "(" << h << ", " << k << ") is in no part";
    EXPECT_TRUE(hit.insert(part).second) << "two regions' points in one part";

    // Its section: every crossing on the region's level, γ3 = 0.
    std::string section_header;
    const auto crossings = csv_rows(out / ("section_" + label + ".csv"), section_header);
    EXPECT_TRUE(std::filesystem::exists(out / ("section_" + label + ".png")));
    EXPECT_GE(crossings.size(), 3u) << "each of the 3 orbits crosses";
    ASSERT_EQ(section_header.rfind("orbit,crossing,t,omega1,omega2,omega3,gamma1,gamma2,gamma3", 0),
              0u);
    std::set<std::string> orbits;
    std::set<int> surfaces;
    double worst = 0;
    for (const auto& c : crossings) {
      orbits.insert(c[0]);
      const double w1 = std::stod(c[3]), w2 = std::stod(c[4]), w3 = std::stod(c[5]);
      const double g1 = std::stod(c[6]), g2 = std::stod(c[7]), g3 = std::stod(c[8]);
      // I = (2, 2, 1), r = (1, 0, 0), P = 1.
      const double energy = 0.5 * (2 * w1 * w1 + 2 * w2 * w2 + w3 * w3) + g1;
      const double area = 2 * w1 * g1 + 2 * w2 * g2 + w3 * g3;
      const double x = w1 * w1 - w2 * w2 - g1, y = 2 * w1 * w2 - g2;
      const double kov = x * x + y * y;
      // On the section's surface: γ3 = 0, or γ1 = 0 or γ2 = 0 for orbits
      // that never cross that (app/diagram_sections.hpp), one for all.
      const std::array<double, 3> g{g1, g2, g3};
      const auto on = std::min_element(
          g.begin(), g.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
      EXPECT_LE(std::abs(*on), 1e-9);
      surfaces.insert(int(on - g.begin()));
      EXPECT_NEAR(g1 * g1 + g2 * g2 + g3 * g3, 1.0, 1e-6);
      worst = std::max({worst, std::abs(energy - h) / std::max(1.0, std::abs(h)),
                        std::abs(area - kArea), std::abs(kov - k) / std::max(1.0, std::abs(k))});
    }
    EXPECT_LE(worst, 1e-6);
    EXPECT_EQ(orbits.size(), 3u);
    EXPECT_EQ(surfaces.size(), 1u);
  }
  EXPECT_EQ(int(hit.size()), parts.count) << "a part without a region";
  // The figure's file and the diagram's, marked.
  EXPECT_TRUE(std::filesystem::exists(out / "diagram.png"));
}

// The preset Lagrange top (I = (2, 2, 1), r = (0, 0, 1), P = 4): its
// regions' sections keep C1, C0 and Ω3 of their points, computed here.
TEST(DiagramSections, LagrangeSectionsKeepTheirLevel) {
  TempDir dir;
  const auto out = dir / "lag";
  const auto r = run_epviz(
      "diagram --case lagrange --area 5 --sections 2 --section-crossings 20 --out " + out.string(),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string header;
  const auto regions = csv_rows(out / "regions.csv", header);
  ASSERT_GE(regions.size(), 1u);
  for (const auto& row : regions) {
    SCOPED_TRACE("region " + row[0]);
    const double h = std::stod(row[1]), n = std::stod(row[2]);
    const auto crossings = csv_rows(out / ("section_" + row[0] + ".csv"), header);
    EXPECT_GE(crossings.size(), 2u);
    for (const auto& c : crossings) {
      const double w1 = std::stod(c[3]), w2 = std::stod(c[4]), w3 = std::stod(c[5]);
      const double g1 = std::stod(c[6]), g2 = std::stod(c[7]), g3 = std::stod(c[8]);
      const double energy = 0.5 * (2 * w1 * w1 + 2 * w2 * w2 + w3 * w3) + 4 * g3;
      EXPECT_NEAR(energy, h, 1e-6 * std::max(1.0, std::abs(h)));
      EXPECT_NEAR(2 * w1 * g1 + 2 * w2 * g2 + w3 * g3, 5.0, 1e-6 * 5.0);
      EXPECT_NEAR(w3, n, 1e-6 * std::max(1.0, std::abs(n)));
    }
  }
}

// The classification the count rests on tells the regions apart, and joins
// the two sides of the wedge round the cusp.
TEST(DiagramSections, TheClosedFormPartsTellRegionsApart) {
  EXPECT_NE(classify(2.5, 0.5), classify(2.5, 2.0));  // below / above the lower arm
  EXPECT_NE(classify(2.5, 3.0), classify(2.5, 8.0));  // under class II / above
  EXPECT_EQ(classify(0.0, 1.0), classify(2.5, 8.0));  // round the cusp's left
  EXPECT_EQ(classify(2.5, 11.0), -1);                 // above the image
}

TEST(DiagramSections, BadValuesAreRefusedBeforeAnyWork) {
  TempDir dir;
  const std::string out = " --out " + (dir / "o").string();
  struct Refused {
    std::string args, must_name;
  };
  const std::vector<Refused> cases = {
      {"--sections 0", "--sections"},
      {"--sections 65", "--sections"},
      {"--sections two", "--sections"},
      {"--sections 3 --section-crossings 0", "--section-crossings"},
      {"--sections 3 --section-crossings 1e9", "--section-crossings"},
      {"--section-crossings 10", "--section-crossings: only with --sections"},
      {"--sections 3 --samples 100", "--samples"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    test::expect_bad_input(run_epviz("diagram --case kovalevskaya --area 0.5 " + c.args + out, dir),
                           c.must_name);
    EXPECT_EQ(dir.file_count(), 0u) << "written despite the error";
  }
}

}  // namespace
}  // namespace epviz
