// `epviz diagram`: the CSV's points lie on their closed-form curves, the
// figure is drawn and not blank, and bad input is refused before any work
// with nothing written.
#include <gtest/gtest.h>

#include <stb/stb_image.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace epviz {
namespace {

using test::run_epviz;
using test::TempDir;

struct Row {
  std::string curve;
  double energy = 0, integral = 0;
};

std::vector<Row> read_rows(const std::filesystem::path& csv, std::string& header) {
  std::ifstream in(csv);
  std::getline(in, header);
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    std::stringstream s(line);
    Row r;
    std::string e, k;
    std::getline(s, r.curve, ',');
    std::getline(s, e, ',');
    std::getline(s, k);
    r.energy = std::stod(e);
    r.integral = std::stod(k);
    rows.push_back(r);
  }
  return rows;
}

// How far (h, k) is from the named curve of the preset Kovalevskaya top
// (ε = 1) at area l, in k.
double kovalevskaya_miss(const Row& r, double l) {
  const double h = r.energy, k = r.integral;
  if (r.curve == "class_I") return std::abs(k);
  if (r.curve == "class_II") return std::abs(k - (h - l * l / 2) * (h - l * l / 2));
  // h = s + l²/(4s²): s is a root of s³ − h s² + l²/4.
  Eigen::Matrix3d companion;
  companion << h, 0, -l * l / 4, 1, 0, 0, 0, 1, 0;
  double best = INFINITY;
  for (const auto& s : companion.eigenvalues()) {
    if (std::abs(s.imag()) > 1e-7 || (r.curve == "s_negative") != (s.real() < 0)) continue;
    const double x = s.real();
    best = std::min(best,
                    std::abs(k - (1 - l * l / (2 * x) + std::pow(l, 4) / (16 * std::pow(x, 4)))));
  }
  return best;
}

// Dark pixels (axes, text) and coloured ones (series) of a PNG.
std::pair<long, long> ink(const std::filesystem::path& png) {
  int w = 0, h = 0, n = 0;
  unsigned char* pixels = stbi_load(png.c_str(), &w, &h, &n, 4);
  if (!pixels) return {0, 0};
  long dark = 0, coloured = 0;
  for (long i = 0; i < long(w) * h; ++i) {
    const unsigned char* p = pixels + 4 * i;
    dark += p[0] < 100 && p[1] < 100 && p[2] < 100;
    coloured += std::abs(int(p[0]) - int(p[2])) > 60 || std::abs(int(p[1]) - int(p[2])) > 60;
  }
  stbi_image_free(pixels);
  return {dark, coloured};
}

TEST(DiagramCommand, KovalevskayaCsvFollowsTheCurvesAndTheFigureIsDrawn) {
  TempDir dir;
  const auto out = dir / "kov";
  const auto r =
      run_epviz("diagram --case kovalevskaya --area 0.5 --samples 3000 --out " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string header;
  const auto rows = read_rows(out / "diagram.csv", header);
  EXPECT_EQ(header, "curve,energy,integral");
  std::map<std::string, int> per_curve;
  for (const auto& row : rows) {
    ++per_curve[row.curve];
    EXPECT_LE(kovalevskaya_miss(row, 0.5), 1e-6 * (1 + std::abs(row.integral)))
        << row.curve << " at (" << row.energy << ", " << row.integral << ")";
  }
  EXPECT_GE(per_curve.size(), 3u);
  // The check can fail: a class II point read as class I is off its curve.
  EXPECT_GT(kovalevskaya_miss({"class_I", 2.0, 3.5}, 0.5), 1.0);
  EXPECT_EQ(test::line_count(test::slurp(out / "sampled.csv")), 3001u);
  const auto [dark, coloured] = ink(out / "diagram.png");
  EXPECT_GT(dark, 2000) << "no axes or labels";
  EXPECT_GT(coloured, 2000) << "no curves or dots";
  EXPECT_NE(r.out.find("diagram.png"), std::string::npos) << r.out;
}

TEST(DiagramCommand, LagrangeAsSvg) {
  TempDir dir;
  const auto out = dir / "lag";
  const auto r = run_epviz(
      "diagram --case lagrange --area 5 --samples 500 --format svg --out " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string header;
  std::map<std::string, int> per_curve;
  for (const auto& row : read_rows(out / "diagram.csv", header)) ++per_curve[row.curve];
  EXPECT_GT(per_curve["precession_large"], 10);
  EXPECT_GT(per_curve["precession_small"], 10);
  EXPECT_EQ(per_curve["sleeping_up"], 1);
  EXPECT_EQ(per_curve["sleeping_down"], 1);
  EXPECT_NE(test::slurp(out / "diagram.svg").find("<svg"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(out / "diagram.png"));
}

struct Refused {
  std::string args, must_name;
};

TEST(DiagramCommand, BadInputIsRefusedBeforeAnyWork) {
  TempDir dir;
  const std::string out = " --out " + (dir / "o").string();
  const std::vector<Refused> cases = {
      {"--case hess --area 1",
       "--case: 'hess' has no bifurcation diagram (allowed: kovalevskaya, lagrange)"},
      {"--case nope --area 1", "--case: 'nope'"},
      {"--case kovalevskaya --area nan", "--area"},
      {"--case kovalevskaya --area 1x", "--area"},
      {"--case kovalevskaya --area 9",
       "--area: the kovalevskaya diagram is computed for |C0| up to 8"},
      {"--case kovalevskaya --area 0.5 --energy-max -3", "--energy-max"},
      {"--case kovalevskaya --area 0.5 --energy-max inf", "--energy-max"},
      {"--case kovalevskaya --area 0.5 --inertia 2,2,1.5", "kovalevskaya needs I1 = I2 = 2 I3"},
      {"--case kovalevskaya --area 0.5 --com 0,0,0", "P a0 = 0"},
      {"--case lagrange --area 5 --com 0.1,0,1", "--inertia, --com, --weight"},
      {"--case lagrange --area 5 --inertia 1,-1,1", "--inertia"},
      {"--case lagrange --area 5 --samples -1", "--samples"},
      {"--case lagrange --area 5 --format eps", "--format"},
      {"--case lagrange --area 5 --gl vulkan", "--gl"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    test::expect_bad_input(run_epviz("diagram " + c.args + out, dir), c.must_name);
    EXPECT_EQ(dir.file_count(), 0u) << "written despite the error";
  }
  dir.write("file", "x");
  test::expect_bad_input(
      run_epviz("diagram --case lagrange --area 5 --out " + (dir / "file").string(), dir), "--out");
}

}  // namespace
}  // namespace epviz
