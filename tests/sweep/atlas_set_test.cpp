// The maps of one sweep drawn as a set (sweep::atlas_figure_set): each takes
// the others as margin peers, so that the painter gives them one plot
// rectangle (tests/paint/heat_map_range_test.cpp checks the rectangles).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "sweep/atlas.hpp"

namespace epviz {
namespace {

using Json = nlohmann::json;

std::vector<Json> rows() {
  std::vector<Json> out;
  for (int i = 0; i < 4; ++i)
    out.push_back({{"index", i},
                   {"axes", {{"energy", double(i % 2)}, {"area_constant", double(i / 2)}}},
                   {"ftle", 0.1 * (i + 1)},
                   {"chaotic_share", 0.25 * i},
                   {"failure", nullptr}});
  return out;
}

TEST(AtlasSet, EveryMapTakesTheOthersAsPeers) {
  const std::vector<sweep::AtlasRequest> requests{{"ftle", "area_constant", "energy", 0.0, 0.3},
                                                  {"chaotic_share", "area_constant", "energy"}};
  const auto figures = sweep::atlas_figure_set(rows(), requests);
  ASSERT_EQ(figures.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& peers = figures[i].heat_map.margin_peers;
    ASSERT_EQ(peers.size(), 1u);
    EXPECT_EQ(peers[0].value_label, figures[1 - i].heat_map.value_label);
    EXPECT_EQ(peers[0].values, figures[1 - i].heat_map.values);
    EXPECT_TRUE(peers[0].margin_peers.empty()) << "peers nest one level only";
  }
  // One map alone has no peers.
  const auto one = sweep::atlas_figures(rows(), requests[0]);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_TRUE(one[0].heat_map.margin_peers.empty());
}

}  // namespace
}  // namespace epviz
