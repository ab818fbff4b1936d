// "Stay in case": after any edit the body satisfies the case's conditions
// (physics::broken_condition is the independent oracle) and keeps the value
// the user edited.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "live/case_constraints.hpp"
#include "physics/cases.hpp"

namespace epviz::live {
namespace {

using physics::Case;

class StayInCase : public ::testing::TestWithParam<Case> {};

TEST_P(StayInCase, EveryEditEndsInsideTheCaseKeepingTheEditedValue) {
  const Case c = GetParam();
  const auto& p = physics::preset(c);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> factor(0.7, 1.4), shift(-0.5, 0.5);
  for (int trial = 0; trial < 50; ++trial) {
    for (Edited what : {Edited::inertia_1, Edited::inertia_2, Edited::inertia_3, Edited::com,
                        Edited::weight, Edited::omega, Edited::gamma}) {
      physics::Body body = p.body;
      physics::InitialState s = p.initial;
      double kept = 0.0;
      switch (what) {
        case Edited::inertia_1: kept = body.inertia.x() *= factor(rng); break;
        case Edited::inertia_2: kept = body.inertia.y() *= factor(rng); break;
        case Edited::inertia_3: kept = body.inertia.z() *= factor(rng); break;
        case Edited::com:
          body.com += Eigen::Vector3d(shift(rng), shift(rng), shift(rng));
          kept = body.com.x();
          break;
        case Edited::weight: kept = body.weight *= factor(rng); break;
        case Edited::omega: s.omega += Eigen::Vector3d(shift(rng), shift(rng), shift(rng)); break;
        case Edited::gamma:
          s.gamma = (s.gamma + Eigen::Vector3d(shift(rng), shift(rng), shift(rng))).normalized();
          break;
      }
      // Hess needs ordered moments; an edit that breaks the order is reported, not repaired.
      if (c == Case::hess &&
          !(body.inertia.x() > body.inertia.y() && body.inertia.y() > body.inertia.z()))
        continue;
      const physics::InitialState before = s;
      enforce_case(c, what, body, s);
      const auto broken = physics::broken_condition(c, body, s);
      EXPECT_FALSE(broken) << physics::case_name(c) << " edit " << int(what) << ": " << *broken;
      switch (what) {
        case Edited::inertia_1: EXPECT_EQ(body.inertia.x(), kept); break;
        case Edited::inertia_2: EXPECT_EQ(body.inertia.y(), kept); break;
        case Edited::inertia_3:
          if (c != Case::lagrange) {  // Lagrange ties only I1 and I2
            EXPECT_EQ(body.inertia.z(), kept);
          }
          break;
        case Edited::com:
          if (c != Case::euler && c != Case::lagrange) {
            EXPECT_EQ(body.com.x(), kept);
          }
          break;
        case Edited::weight: EXPECT_EQ(body.weight, kept); break;
        case Edited::gamma: EXPECT_EQ(s.gamma, before.gamma); break;
        case Edited::omega: break;
      }
    }
  }
}

// Every row of the case table with conditions, so that a new case is edited too.
std::vector<Case> cases_with_conditions() {
  std::vector<Case> out;
  for (const auto& p : physics::case_presets())
    if (p.fit) out.push_back(p.id);
  return out;
}

INSTANTIATE_TEST_SUITE_P(Cases, StayInCase, ::testing::ValuesIn(cases_with_conditions()),
                         [](const auto& param_info) {
                           std::string n = physics::case_name(param_info.param);
                           for (char& ch : n)
                             if (ch == '-') ch = '_';
                           return n;
                         });

TEST(StayInCase, GenericAndCustomBodiesAreLeftAlone) {
  physics::Body body{{1.0, 2.5, 3.2}, {0.3, -0.2, 0.1}, 1.5};
  physics::InitialState s{{0.1, 0.2, 0.3}, {0.0, 0.6, 0.8}};
  const auto b0 = body;
  enforce_case(Case::generic, Edited::inertia_1, body, s);
  enforce_case(Case::custom, Edited::com, body, s);
  EXPECT_EQ(body.inertia, b0.inertia);
  EXPECT_EQ(body.com, b0.com);
}

}  // namespace
}  // namespace epviz::live
