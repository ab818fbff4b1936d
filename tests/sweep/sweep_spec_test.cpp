#include <gtest/gtest.h>

#include <cmath>

#include "io/json_reader.hpp"
#include "job/schema.hpp"
#include "sweep/sweep_point.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;

SweepSpec parse(const std::string& text) { return read_sweep(Json::parse(text), "s.json"); }

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const io::BadInput& e) {
    return e.what();
  }
  return "";
}

TEST(SweepSpec, PointsAreTheProductWithTheFirstAxisSlowest) {
  const auto s = parse(R"({"axes": [{"field": "method", "values": ["rk4", "gauss4"]},
                                    {"field": "step", "values": [0.1, 0.2, 0.3]},
                                    {"field": "weight", "values": [1, 2]}]})");
  ASSERT_EQ(s.point_count(), 12);
  long index = 0;
  for (std::size_t a = 0; a < 2; ++a)
    for (std::size_t b = 0; b < 3; ++b)
      for (std::size_t c = 0; c < 2; ++c)
        EXPECT_EQ(s.coordinates(index++), (std::vector<std::size_t>{a, b, c}));
}

TEST(SweepSpec, RangesIncludeBothEndsEvenlySpaced) {
  const auto s =
      parse(R"({"axes": [{"field": "step", "from": 0.001, "to": 0.1, "count": 5, "scale": "log"},
                                    {"field": "weight", "from": -1, "to": 1, "count": 5}]})");
  const auto& log = s.axes[0].values;
  ASSERT_EQ(log.size(), 5u);
  EXPECT_EQ(log.front().get<double>(), 0.001);
  EXPECT_EQ(log.back().get<double>(), 0.1);
  for (int i = 1; i < 4; ++i)
    EXPECT_NEAR(log[i].get<double>() / log[i - 1].get<double>(), std::pow(10.0, 0.5), 1e-12);
  const auto& lin = s.axes[1].values;
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(lin[i].get<double>(), -1.0 + 0.5 * i, 1e-15);
}

TEST(SweepSpec, HashIsOfTheContentNotItsSpelling) {
  const auto a = parse(R"({"axes": [{"field": "step", "values": [0.1]}], "reference": true})");
  const auto b = parse(R"({ "reference" : true,
      "axes":[{"values":[0.1],"field":"step"}] })");
  const auto c = parse(R"({"axes": [{"field": "step", "values": [0.2]}], "reference": true})");
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_NE(a.hash, c.hash);
}

TEST(SweepSpec, BadFilesNameTheKeyAndWhatIsAllowed) {
  struct Case {
    const char* text;
    const char* key;
    const char* says;
  };
  for (
      const auto& c : std::vector<Case>{
          {R"({"axes": [{"field": "stepp", "values": [1]}]})", "'axes[0].field'", "inertia[0]"},
          {R"({"axes": []})", "'axes'", "1 to 16"},
          {R"({})", "'axes'", "missing"},
          {R"({"axes": [{"field": "step", "values": [0.1]}], "extra": 1})", "'extra'", "unknown"},
          {R"({"axes": [{"field": "step", "values": [0.1], "from": 1}]})", "'axes[0].values'",
           "not both"},
          {R"({"axes": [{"field": "step", "from": -1, "to": 1, "count": 3, "scale": "log"}]})",
           "'axes[0].from'", "positive"},
          {R"({"axes": [{"field": "method", "values": [4]}]})", "'axes[0].values[0]'", "strings"},
          {R"({"axes": [{"field": "method", "from": 1, "to": 2, "count": 2}]})", "'axes[0].from'",
           "values"},
          {R"({"axes": [{"field": "step", "values": [1]}, {"field": "step", "values": [2]}]})",
           "'axes[1].field'", "already"},
          {R"({"simulation": {"tol": "x"}, "axes": [{"field": "step", "values": [1]}]})",
           "'simulation.tol'", ""},
          {R"({"axes": [{"field": "step", "values": [1]}], "atlas": [{"metric": "ftle", "x": "step", "y": "energy"}]})",
           "'atlas[0].y'", "not one of the sweep's axes"},
          {R"({"axes": [{"field": "step", "values": [1]}], "atlas": [{"metric": "ftle", "x": "step", "y": "step", "min": 1, "max": 0}]})",
           "'atlas[0].max'", "larger than \"min\""},
          {R"({"axes": [{"field": "step", "from": 0.1, "to": 1, "count": 13}], "ftle": {"curve": true}})",
           "'ftle'", "at most 12 points (merge draws every curve in one chart), this sweep has 13"},
          {R"({"axes": [{"field": "energy", "values": [3]}, {"field": "area_constant", "values": [0]}],
               "level_orbits": 4, "ftle": {"curve": true}})",
           "'ftle'", "not an energy-momentum map"},
          {R"({"axes": [{"field": "step", "values": [1]}], "ftle": {"curve": 1}})", "'ftle.curve'",
           ""},
      }) {
    const std::string e = error_of(c.text);
    EXPECT_NE(e.find(c.key), std::string::npos) << c.text << " -> " << e;
    EXPECT_NE(e.find(c.says), std::string::npos) << c.text << " -> " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

TEST(SweepPoint, ComponentAxesChangeOneComponentOfThePresetsVector) {
  const auto s = parse(R"({"simulation": {"case": "generic"},
      "axes": [{"field": "inertia[1]", "values": [1.5, 1.9]}, {"field": "method", "values": ["rk4"]}]})");
  const auto p = point_fields(s, 1);
  ASSERT_TRUE(p.fields.inertia);
  const auto& generic = physics::preset(physics::Case::generic).body.inertia;
  EXPECT_EQ((*p.fields.inertia)[0], generic[0]);
  EXPECT_EQ((*p.fields.inertia)[1], 1.9);
  EXPECT_EQ((*p.fields.inertia)[2], generic[2]);
  EXPECT_EQ(p.axis_values["inertia[1]"], 1.9);
  EXPECT_NE(p.fields.inertia.origin.find("axes[0]"), std::string::npos);
}

// The simulation fields as a job file would hold them, origins aside.
Json written(const job::SimulationFields& fields) {
  job::JobDocument d;
  d.simulation = fields;
  return job::write_job(d)["simulation"];
}

TEST(SweepPoint, AReaderOfManyPointsGivesEachAsReadAlone) {
  // Plain, component and energy axes, values met again and again: the
  // reader keeps what it read of each value, which must not leak from one
  // point into the next.
  const auto s = parse(R"({"simulation": {"case": "generic", "omega": [1, 0.5, 0.2]},
      "axes": [{"field": "method", "values": ["rk4", "dop853"]},
               {"field": "omega[1]", "from": -1, "to": 1, "count": 3},
               {"field": "step", "values": [0.01, 0.02]},
               {"field": "energy", "values": [4, 5]},
               {"field": "weight", "values": [1, 2]}]})");
  PointReader read(s);
  for (long i = 0; i < s.point_count(); ++i) {
    SCOPED_TRACE("point " + std::to_string(i));
    const PointFields many = read(i);
    const PointFields alone = point_fields(s, i);
    EXPECT_EQ(written(many.fields), written(alone.fields));
    EXPECT_EQ(many.fields.omega.origin, alone.fields.omega.origin);
    EXPECT_EQ(many.fields.weight.origin, alone.fields.weight.origin);
    EXPECT_EQ(many.axis_values, alone.axis_values);
    EXPECT_EQ(many.energy, alone.energy);
    EXPECT_EQ(many.energy_origin, alone.energy_origin);
    EXPECT_EQ(many.ignored, alone.ignored);
  }
  // And what the points are, independently of the reader: the last point.
  const PointFields last = read(s.point_count() - 1);
  EXPECT_EQ(*last.fields.method, "dop853");
  EXPECT_EQ((*last.fields.omega)[0], 1.0);
  EXPECT_EQ((*last.fields.omega)[1], 1.0);
  EXPECT_EQ(*last.fields.weight, 2.0);
  EXPECT_EQ(last.energy, 5.0);
  EXPECT_EQ(last.ignored, std::vector<std::string>{"step"});
}

TEST(SweepPoint, AReaderChecksAComponentsValueAtTheFirstPointThatTakesIt) {
  const auto s = parse(R"({"axes": [{"field": "omega[2]", "values": [0.5, 1e300]}]})");
  PointReader read(s);
  EXPECT_NO_THROW(read(0));
  try {
    read(1);
    ADD_FAILURE() << "an omega component of 1e300 was taken";
  } catch (const io::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("axes[0]"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(read(0));
}

TEST(SweepPoint, AStepAxisDoesNotApplyToAdaptiveMethods) {
  const auto s = parse(R"({"axes": [{"field": "method", "values": ["rk4", "dop853"]},
                                    {"field": "step", "values": [0.05]}]})");
  const auto fixed = point_fields(s, 0);
  ASSERT_TRUE(fixed.fields.step);
  EXPECT_EQ(*fixed.fields.step, 0.05);
  EXPECT_TRUE(fixed.ignored.empty());
  const auto adaptive = point_fields(s, 1);
  EXPECT_FALSE(adaptive.fields.step);
  EXPECT_EQ(adaptive.ignored, std::vector<std::string>{"step"});
}

TEST(SweepPoint, EnergyLevelScalesOmegaToTheTotalEnergy) {
  sim::RunSpec run;
  run.body = {{1.0, 1.7, 2.3}, {0.6, 0.4, 0.7}, 2.0};
  run.initial = {{1.0, 0.8, 0.6}, {0.0, 0.6, 0.8}};
  set_energy(run, 3.0, "here");
  // C1 = 1/2 sum I_i w_i^2 + P a.gamma, computed here by hand.
  const auto& w = run.initial.omega;
  const double c1 = 0.5 * (1.0 * w[0] * w[0] + 1.7 * w[1] * w[1] + 2.3 * w[2] * w[2]) +
                    2.0 * (0.4 * 0.6 + 0.7 * 0.8);
  EXPECT_NEAR(c1, 3.0, 1e-12);
  EXPECT_NEAR(w[1] / w[0], 0.8, 1e-15);  // direction kept
  EXPECT_NEAR(w[2] / w[0], 0.6, 1e-15);
  // Below the potential energy 2 * 0.8 = 1.6 of this gamma there is no such omega.
  try {
    set_energy(run, 1.5, "s.json: key 'axes[2]'");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("axes[2]"), std::string::npos);
  }
}

}  // namespace
}  // namespace epviz::sweep
