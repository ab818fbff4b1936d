// A render job's "overlay_place": read, written back (only when not the
// default), and anything else refused naming the key and the places allowed.
#include <gtest/gtest.h>

#include <string>

#include "io/bad_input.hpp"
#include "job/schema.hpp"

namespace epviz {
namespace {

job::JobDocument read(const std::string& place) {
  return job::read_job(nlohmann::json::parse(R"({"simulation": {"case": "generic"},
    "overlay_place": ")" + place + "\"}"),
                       "job.json");
}

TEST(OverlayPlaceKey, ReadsAndWritesBack) {
  for (const auto place : {scene::OverlayPlace::beside, scene::OverlayPlace::top_right,
                           scene::OverlayPlace::bottom_left}) {
    const auto doc = read(std::string(scene::name(place)));
    EXPECT_EQ(doc.scene.page.overlay, place);
    const auto back = job::read_job(nlohmann::json::parse(job::write_job(doc).dump()), "job.json");
    EXPECT_EQ(back.scene.page.overlay, place);
  }
  const auto plain =
      job::read_job(nlohmann::json::parse(R"({"simulation": {"case": "generic"}})"), "job.json");
  EXPECT_EQ(plain.scene.page.overlay, scene::OverlayPlace::automatic);
  EXPECT_FALSE(job::write_job(plain).contains("overlay_place"));
}

TEST(OverlayPlaceKey, AnotherPlaceIsRefusedNamingTheKeyAndThePlaces) {
  try {
    read("middle");
    FAIL() << "accepted";
  } catch (const io::BadInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("overlay_place"), std::string::npos) << what;
    EXPECT_NE(what.find("bottom-right"), std::string::npos) << what;
    EXPECT_NE(what.find("middle"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace epviz
