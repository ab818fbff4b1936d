// A figure's printed size: lengths in four units read to points, the font
// and dpi in their ranges, the layout's units (1/dpi inch), and every
// mistake one line naming the option, quoting the value and saying what is
// allowed.
#include <gtest/gtest.h>

#include <string>

#include "io/bad_input.hpp"
#include "io/print_size.hpp"
#include "support/errors.hpp"

namespace epviz {
namespace {

using test::error_of;

TEST(PrintSize, LengthsInEachUnitAreReadToPoints) {
  // 1 in = 25.4 mm = 72 pt.
  EXPECT_NEAR(io::parse_length_pt("--w", "85mm"), 240.944, 1e-3);
  EXPECT_NEAR(io::parse_length_pt("--w", "8.5cm"), 240.944, 1e-3);
  EXPECT_DOUBLE_EQ(io::parse_length_pt("--w", "3.5in"), 252.0);
  EXPECT_DOUBLE_EQ(io::parse_length_pt("--w", "241pt"), 241.0);
  EXPECT_DOUBLE_EQ(io::parse_length_pt("--w", "1in"), 72.0);     // the least
  EXPECT_DOUBLE_EQ(io::parse_length_pt("--w", "20in"), 1440.0);  // the most
}

TEST(PrintSize, ALengthWithoutItsUnitOrOutOfRangeIsRefused) {
  for (const char* bad : {"85", "85 mm", "85MM", "mm", "", "85px", "in", "nanmm", "8,5cm"})
    EXPECT_EQ(error_of<io::BadInput>([&] { io::parse_length_pt("--figure-width", bad); }),
              std::string("--figure-width: expected a length such as 85mm, 8.5cm, 3.5in or "
                          "241pt, got '") +
                  bad + "'")
        << bad;
  for (const char* far : {"0.1in", "20.5in", "0mm", "-85mm", "600mm"})
    EXPECT_EQ(error_of<io::BadInput>([&] { io::parse_length_pt("--figure-width", far); }),
              std::string("--figure-width: '") + far + "' is outside 1in to 20in (72pt to 1440pt)")
        << far;
}

TEST(PrintSize, FontAndDpiWithinTheirRanges) {
  EXPECT_DOUBLE_EQ(io::parse_font_pt("--font-size", "9.5"), 9.5);
  EXPECT_DOUBLE_EQ(io::parse_dpi("--dpi", "600"), 600.0);
  EXPECT_EQ(error_of<io::BadInput>([] { io::parse_font_pt("--font-size", "2"); }),
            "--font-size: '2' is outside 5 pt to 24 pt");
  EXPECT_EQ(error_of<io::BadInput>([] { io::parse_font_pt("--font-size", "8pt"); }),
            "--font-size: expected a finite number, got '8pt'");
  EXPECT_EQ(error_of<io::BadInput>([] { io::parse_dpi("--dpi", "1201"); }),
            "--dpi: '1201' is outside 72 dpi to 1200 dpi");
}

TEST(PrintSize, NoneGivenIsAScreenFigure) { EXPECT_FALSE(io::parse_print_size({}).has_value()); }

TEST(PrintSize, DefaultsAndTheLayoutsUnits) {
  const auto size = io::parse_print_size({"85mm", "", ""});
  ASSERT_TRUE(size.has_value());
  EXPECT_DOUBLE_EQ(size->font_pt, 8.0);
  EXPECT_DOUBLE_EQ(size->dpi, 300.0);
  // 85 mm at 300 dpi: 3.346 in, 1003.9 px; 8 pt is 1/9 in, 33.3 px.
  EXPECT_EQ(size->width_units(), 1004);
  EXPECT_NEAR(size->font_units(), 33.333f, 1e-3f);
  EXPECT_DOUBLE_EQ(size->units_per_pt() * size->pt_per_unit(), 1.0);
  // The page in points differs from the width asked by under half a unit.
  EXPECT_NEAR(size->width_units() * size->pt_per_unit(), size->width_pt, 0.5 * size->pt_per_unit());

  const auto given = io::parse_print_size({"3.5in", "10", "200"});
  ASSERT_TRUE(given.has_value());
  EXPECT_EQ(given->width_units(), 700);
  EXPECT_FLOAT_EQ(given->font_units(), 10.0f * 200.0f / 72.0f);
}

TEST(PrintSize, FontOrDpiWithoutAWidthIsRefusedNamingTheWidth) {
  EXPECT_EQ(error_of<io::BadInput>([] {
              io::parse_print_size({"", "8", ""});
            }),
            "--font-size: applies to a figure of a printed size; give --figure-width too");
  EXPECT_EQ(error_of<io::BadInput>([] {
              io::parse_print_size({"", "", "300"});
            }),
            "--dpi: applies to a figure of a printed size; give --figure-width too");
  // Other names (a file's keys) are used as given.
  EXPECT_EQ(error_of<io::BadInput>([] {
              io::parse_print_size({"", "8", ""}, "W", "F", "D");
            }),
            "F: applies to a figure of a printed size; give W too");
}

TEST(PrintSize, AWidthOfMorePixelsThanADrawingTakesIsRefused) {
  EXPECT_TRUE(io::parse_print_size({"20in", "", "800"}).has_value());  // 16000 px
  EXPECT_EQ(error_of<io::BadInput>([] {
              io::parse_print_size({"20in", "", "1200"});
            }),
            "--dpi: 20in at 1200 dpi is 24000 pixels wide; at most 16384 (a lower dpi or a "
            "narrower figure)");
}

}  // namespace
}  // namespace epviz
