// The picture's layers come from one table: a Layers starts from each
// layer's default, Layers::only switches on exactly the layers named, and
// each layer is reached by its enum and by its member alike.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "scene/layers.hpp"

namespace epviz::scene {
namespace {

TEST(Layers, StartFromTheTablesDefaults) {
  const Layers l;
  for (const auto& info : layer_table()) {
    EXPECT_EQ(l.*info.member, info.default_on) << info.key;
    EXPECT_EQ(l[info.id], info.default_on) << info.key;
  }
  EXPECT_TRUE(l.any());
}

TEST(Layers, OnlySwitchesOnTheLayersNamed) {
  EXPECT_FALSE(Layers::only({}).any());
  for (const auto& info : layer_table()) {
    const Layers l = Layers::only({info.id});
    EXPECT_TRUE(l.any());
    for (const auto& other : layer_table())
      EXPECT_EQ(l.*other.member, other.id == info.id) << info.key << " " << other.key;
  }
}

TEST(Layers, TheTableIsInEnumOrderWithDistinctKeysMembersAndLabels) {
  std::set<std::string> keys, labels;
  for (std::size_t i = 0; i < layer_table().size(); ++i) {
    const auto& info = layer_table()[i];
    EXPECT_EQ(std::size_t(info.id), i);
    keys.insert(info.key);
    labels.insert(info.panel_label);
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(layer_table()[j].member, info.member) << i;
    Layers l = Layers::only({});
    l[info.id] = true;
    EXPECT_TRUE(l.*info.member) << info.key;
  }
  EXPECT_EQ(keys.size(), layer_count);
  EXPECT_EQ(labels.size(), layer_count);
}

}  // namespace
}  // namespace epviz::scene
