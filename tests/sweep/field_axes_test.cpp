// A sweep's axes come from the simulation's field table: every sweepable
// field is an axis that sets its field per point, named by the axis; and the
// numbers a sweep adds (an FTLE window, an energy level) keep to the ranges
// the table sets.
#include <gtest/gtest.h>

#include <stdexcept>

#include "io/json_reader.hpp"
#include "job/fields.hpp"
#include "job/schema.hpp"
#include "sweep/sweep_point.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;

SweepSpec parse(const std::string& text) { return read_sweep(Json::parse(text), "s.json"); }

// Two values the field accepts, from its own choices or range.
std::vector<Json> two_values(const job::FieldInfo& f) {
  switch (f.type) {
    case job::FieldType::text: {
      const auto comma = f.choices.find(", ");
      const auto second = f.choices.find(", ", comma + 2);
      return {f.choices.substr(0, comma), f.choices.substr(comma + 2, second - comma - 2)};
    }
    case job::FieldType::integer: return {long(f.min), long(f.min) + 7};
    case job::FieldType::vec3: {
      const double a = f.min > 0.0 ? f.min * 2.0 : 0.25;
      return {Json::array({a, a, a}), Json::array({a, 2 * a, a})};
    }
    case job::FieldType::number:
      if (f.min > 0.0) return {f.min * 3.0, f.max * 0.75};  // tol
      return {0.5, 1.5};
    case job::FieldType::flag: break;
  }
  return {};
}

TEST(SweepAxes, EverySweepableFieldIsAnAxisThatSetsItPerPointNamingTheAxis) {
  int swept = 0;
  for (const auto& f : job::simulation_field_table()) {
    if (!f.sweepable) continue;
    SCOPED_TRACE(f.key);
    const auto values = two_values(f);
    ASSERT_EQ(values.size(), 2u);
    Json axis = {{"field", f.key}, {"values", values}};
    Json sweep = {{"axes", Json::array({axis})}};
    // A step applies to a fixed-step method only (the default is adaptive).
    if (f.key == "step") sweep["simulation"] = {{"method", "rk4"}};
    const auto s = read_sweep(sweep, "s.json");
    PointReader read(s);
    for (long i = 0; i < 2; ++i) {
      const auto p = read(i);
      job::JobDocument d;
      d.simulation = p.fields;
      const Json written = Json::parse(job::write_job(d)["simulation"].dump());
      ASSERT_TRUE(written.contains(f.key)) << written.dump();
      EXPECT_EQ(written[f.key], values[std::size_t(i)]);
      std::visit(
          [&](auto m) {
            EXPECT_EQ((p.fields.*m).origin, "s.json: key 'axes[0]' (" + f.key + " = " +
                                                values[std::size_t(i)].dump() + ")");
          },
          f.member);
    }
    ++swept;
  }
  EXPECT_GE(swept, 13);  // every field but the three flags
}

TEST(SweepAxes, TimeSamplesAndDriftAxesSetThoseFields) {
  const auto s = parse(R"({"axes": [{"field": "t_end", "values": [5, 7]},
                                    {"field": "samples", "values": [10, 30]},
                                    {"field": "max_drift", "values": [0.5]}]})");
  PointReader read(s);
  const auto p = read(3);
  EXPECT_EQ(*p.fields.t_end, 7.0);
  EXPECT_EQ(*p.fields.samples, 30);
  EXPECT_EQ(*p.fields.max_drift, 0.5);
  EXPECT_EQ(p.fields.t_end.origin, "s.json: key 'axes[0]' (t_end = 7)");
  EXPECT_EQ(p.fields.samples.origin, "s.json: key 'axes[1]' (samples = 30)");
  EXPECT_EQ(p.fields.max_drift.origin, "s.json: key 'axes[2]' (max_drift = 0.5)");
}

std::string point_error(const SweepSpec& s, long index) {
  try {
    PointReader read(s);
    read(index);
  } catch (const io::BadInput& e) {
    return e.what();
  }
  return "";
}

TEST(SweepAxes, AnFtleWindowIsBoundLikeAStepOverThePointsTEnd) {
  const std::string head =
      R"({"simulation": {"t_end": 2}, "axes": [{"field": "t_end", "values": [2, 4]}], )";
  for (const char* window : {"1e-300", "1e-9"}) {
    SCOPED_TRACE(window);
    const auto s = parse(head + R"("ftle": {"window": )" + window + "}}");
    const auto e = point_error(s, 0);
    EXPECT_NE(e.find("s.json: key 'ftle.window': expected a window from t_end / 1e9"),
              std::string::npos)
        << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  // 2e9 windows of 2e-9 over t_end 2 would be too many, 1e9 is the bound:
  // t_end 2 takes 2e-9, t_end 4 does not.
  const auto s = parse(head + R"("ftle": {"window": 2e-9}})");
  EXPECT_EQ(point_error(s, 0), "");
  EXPECT_NE(point_error(s, 1).find("at point 1, t_end 4"), std::string::npos) << point_error(s, 1);
  EXPECT_EQ(point_error(parse(head + R"("ftle": {"window": 0.5}})"), 1), "");
}

TEST(SweepAxes, AnEnergyLevelMayNotTakeOmegaPastItsRange) {
  sim::RunSpec run;
  run.body = {{1.0, 1.7, 2.3}, {0.6, 0.4, 0.7}, 2.0};
  run.initial = {{1.0, 0.8, 0.6}, {0.0, 0.6, 0.8}};
  // C1 = 1/2 I w^2 + potential: at 1e308, |w| is near 1e154, far past 1e6.
  for (double energy : {1e308, 1e13}) {
    SCOPED_TRACE(energy);
    sim::RunSpec r = run;
    try {
      set_energy(r, energy, "s.json: key 'axes[0]' (energy = 1e308)");
      ADD_FAILURE() << "omega became " << r.initial.omega.transpose();
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("s.json: key 'axes[0]'"), std::string::npos) << what;
      EXPECT_NE(what.find("three numbers from -1e6 to 1e6"), std::string::npos) << what;
    }
  }
  // Kinetic 1.458 |w|^2 / |w0|^2 here: 1e11 gives |w1| near 2.6e5, within reach.
  sim::RunSpec r = run;
  EXPECT_NO_THROW(set_energy(r, 1e11, "here"));
  EXPECT_LE(r.initial.omega.cwiseAbs().maxCoeff(), 1e6);
}

}  // namespace
}  // namespace epviz::sweep
