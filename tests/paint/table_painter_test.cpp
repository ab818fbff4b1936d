// The table painter against a reviewed golden (tests/snapshots/chart_table.png).
#include <gtest/gtest.h>

#include "paint/figure_fixtures.hpp"
#include "paint/table_painter.hpp"
#include "render/render_test_support.hpp"
#include "render/snapshot.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;

TEST(TablePainter, MatchesTheReviewedGolden) {
  paint::TableSpec t{"Stability (test)", {"study", "case", "method", "result"}, {}};
  t.rows = {{"max_step", "kovalevskaya", "rk4", "max step 0.328"},
            {"chaos", "generic", "dop853", "separated no"},
            {"pole", "custom", "dop853", "error 9.27e-10"}};
  const auto img = paint::paint_table(et::shared_gl_context(), t, et::builtin_font_options());
  int ink = 0;
  for (std::size_t i = 0; i < img.pixels.size(); i += 4)
    if (img.pixels[i] < 128) ++ink;
  EXPECT_GT(ink, 500);
  EXPECT_TRUE(et::matches_snapshot("chart_table", img.width, img.height, img.pixels));
}

}  // namespace
}  // namespace epviz
