// The simulation's field table bounds what a job may give, and the picture's
// layer table gives a job's "layers" keys and its at-least-one rule.
#include <gtest/gtest.h>

#include <cmath>

#include "io/json_reader.hpp"
#include "job/fields.hpp"
#include "job/schema.hpp"
#include "scene/layers.hpp"

namespace epviz {
namespace {

using Json = nlohmann::json;

std::string error_of(const Json& j) {
  try {
    job::read_job(j, "job.json");
  } catch (const io::BadInput& e) {
    return e.what();
  }
  return "";
}

Json with_simulation(const std::string& key, const Json& value) {
  Json j = {{"simulation", {{"case", "euler"}}}};
  j["simulation"][key] = value;
  return j;
}

TEST(JobFields, ATolBelowItsRangeIsRefusedNamingTheRange) {
  const auto e = error_of(with_simulation("tol", 1e-16));
  EXPECT_NE(e.find("job.json: key 'simulation.tol': expected a number from 1e-15 to 0.1"),
            std::string::npos)
      << e;
  EXPECT_EQ(error_of(with_simulation("tol", 1e-15)), "");
  EXPECT_NE(error_of(with_simulation("tol", 0.2)).find("1e-15 to 0.1"), std::string::npos);
}

// Just past either end of each field's range (each component of a vector)
// is refused with the range named; the ends themselves are taken.
TEST(JobFields, EveryBoundedFieldKeepsToItsRange) {
  for (const auto& f : job::simulation_field_table()) {
    if (f.type == job::FieldType::text || f.type == job::FieldType::flag) continue;
    SCOPED_TRACE(f.key);
    auto value = [&](double x) {
      if (f.type == job::FieldType::integer) return Json(long(x));
      if (f.type == job::FieldType::vec3) return Json::array({x, x, x});
      return Json(x);
    };
    for (double end : {f.min, f.max}) {
      if (!std::isfinite(end)) continue;
      const bool low = end == f.min;
      const double past = f.type == job::FieldType::integer ? end + (low ? -1.0 : 1.0)
                          : end == 0.0                      ? -1e-300
                                                            : end * (low == (end > 0) ? 0.5 : 2.0);
      const auto e = error_of(with_simulation(f.key, value(past)));
      EXPECT_NE(e.find("key 'simulation." + f.key + "': expected " + f.range_text()),
                std::string::npos)
          << past << " -> " << e;
      if (!(low && f.min_exclusive)) {
        EXPECT_EQ(error_of(with_simulation(f.key, value(end))), "") << end;
      }
    }
  }
}

Json with_layers(const scene::Layers& l) {
  Json layers = Json::object();
  for (const auto& info : scene::layer_table()) layers[info.key] = l.*info.member;
  return {{"simulation", {{"case", "euler"}}}, {"layers", layers}};
}

TEST(JobLayers, EveryLayerKeyReadsAndWritesBack) {
  for (const auto& info : scene::layer_table()) {
    SCOPED_TRACE(info.key);
    const auto alone = scene::Layers::only({info.id});
    const auto d = job::read_job(with_layers(alone), "job.json");
    for (const auto& other : scene::layer_table())
      EXPECT_EQ(d.scene.layers[other.id], other.id == info.id) << other.key;
    const Json written = Json::parse(job::write_job(d).dump());
    for (const auto& other : scene::layer_table())
      EXPECT_EQ(written["layers"][other.key], other.id == info.id) << other.key;
    const auto again = job::read_job(written, "again.json");
    for (const auto& other : scene::layer_table())
      EXPECT_EQ(again.scene.layers[other.id], other.id == info.id) << other.key;
  }
  // A job that names no layer draws each as its default.
  const auto d = job::read_job(Json{{"simulation", {{"case", "euler"}}}}, "job.json");
  for (const auto& info : scene::layer_table())
    EXPECT_EQ(d.scene.layers[info.id], info.default_on) << info.key;
}

TEST(JobLayers, AtLeastOneLayerIsOn) {
  const auto e = error_of(with_layers(scene::Layers::only({})));
  EXPECT_NE(e.find("every layer is switched off"), std::string::npos) << e;
  for (const auto& info : scene::layer_table())
    EXPECT_EQ(error_of(with_layers(scene::Layers::only({info.id}))), "") << info.key;
}

}  // namespace
}  // namespace epviz
