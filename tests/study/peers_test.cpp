// Peers: each library integrates the same problem as epviz, so at tol 1e-10
// it reaches epviz's DOP853 tol-1e-13 final state closely, and its error falls
// with the tolerance.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <string>

#include "io/subprocess.hpp"
#include "sim/simulate.hpp"
#include "study/peers/peers.hpp"
#include "study/peers/scipy_peer.hpp"
#include "study/reference.hpp"

namespace epviz::study::peers {
namespace {

constexpr double kTEnd = 10.0;

sim::RunSpec kovalevskaya(double tol) {
  auto spec = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                              sim::Formulation::direct, kTEnd, 1);
  spec.tol = tol;
  return spec;
}

const sim::Sample& reference_end() {
  static const sim::Sample s = [] {
    const auto r = sim::simulate(kovalevskaya(1e-13));
    EXPECT_FALSE(r.failure);
    return r.samples.back();
  }();
  return s;
}

double error_of(const PeerResult& r) {
  sim::Sample s;
  s.t = r.t;
  s.omega = r.omega;
  s.gamma = r.gamma;
  return study::state_error(s, reference_end());
}

// Why the peer cannot run on this machine, "" when it can. Only SciPy may be
// absent (GSL's peers are offered only where GSL was found), and that is asked
// of python3 directly, not of the peer: a peer that is there but fails to
// start, or skips for any other reason, fails its test.
std::string why_absent(PeerId id) {
  if (impl_name(id) != "scipy") return "";
  static const std::string why = [] {
    if (::access("/usr/bin/python3", X_OK) != 0) return std::string("no /usr/bin/python3");
    const auto r = io::run_process({"/usr/bin/python3", "-c", "import scipy"});
    return r.status.success() ? std::string() : "/usr/bin/python3 cannot import scipy";
  }();
  return why;
}

class PeerTest : public ::testing::TestWithParam<PeerId> {};

TEST_P(PeerTest, ReachesEpvizFinalStateOnKovalevskaya) {
  const PeerId id = GetParam();
  if (const auto why = why_absent(id); !why.empty()) GTEST_SKIP() << why;
  const auto r = run_peer(id, kovalevskaya(1e-10), 1);
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_DOUBLE_EQ(r.t, kTEnd);
  EXPECT_GT(r.rhs_evals, 0);
  const double err = error_of(r);
  RecordProperty("error", std::to_string(err));
  EXPECT_LT(err, 1e-7) << impl_name(id) << " " << method_name(id);
}

TEST_P(PeerTest, ErrorFallsWithTolerance) {
  const PeerId id = GetParam();
  if (const auto why = why_absent(id); !why.empty()) GTEST_SKIP() << why;
  const auto loose = run_peer(id, kovalevskaya(1e-5), 1);
  const auto tight = run_peer(id, kovalevskaya(1e-10), 1);
  ASSERT_TRUE(loose.ok()) << loose.reason;
  ASSERT_TRUE(tight.ok()) << tight.reason;
  EXPECT_LT(10.0 * error_of(tight), error_of(loose));
  EXPECT_GT(tight.rhs_evals, loose.rhs_evals);
}

INSTANTIATE_TEST_SUITE_P(All, PeerTest, ::testing::ValuesIn(all_peers()),
                         [](const ::testing::TestParamInfo<PeerId>& param_info) {
                           std::string s =
                               impl_name(param_info.param) + "_" + method_name(param_info.param);
                           for (char& c : s)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return s;
                         });

TEST(ScipyPeer, SkipsWithAMessageWhenScipyIsAbsent) {
  // A missing driver script reads the same as a missing scipy (or python3,
  // looked for first): skipped, with the reason.
  setenv("EPVIZ_SCIPY_DRIVER", "/nonexistent/scipy_driver.py", 1);
  const auto r = run_scipy_peers(physics::Body{}, physics::InitialState{}, 0.1, {1e-6, 1e-8}, 1);
  unsetenv("EPVIZ_SCIPY_DRIVER");
  ASSERT_EQ(r.solve_ivp.size(), 2u);
  for (const auto& p : r.solve_ivp) {
    EXPECT_EQ(p.status, PeerStatus::skipped);
    EXPECT_NE(p.reason.find("not found"), std::string::npos) << p.reason;
  }
}

TEST(PeerWorkPrecision, OneRowPerPeerAndTolerance) {
  const std::vector<double> tols{1e-6, 1e-9};
  const auto& k = physics::preset(physics::Case::kovalevskaya);
  const auto rows = peer_work_precision(k.body, k.initial, tols, kTEnd, 1);
  ASSERT_EQ(rows.size(), all_peers().size() * tols.size());
  for (const auto& row : rows) {
    const std::string impl = impl_name(row.id), method = method_name(row.id);
    EXPECT_TRUE(impl == "boost-odeint" || impl == "gsl" || impl == "scipy") << impl;
    EXPECT_EQ(row.t_end, kTEnd);
    const auto& r = row.result;
    if (!why_absent(row.id).empty()) {
      EXPECT_EQ(r.status, PeerStatus::skipped) << method;
      continue;
    }
    EXPECT_TRUE(r.ok()) << method << ": " << r.reason;
    EXPECT_GT(r.cpu_seconds, 0.0) << method;
    EXPECT_GT(r.rhs_evals, 0) << method;
    EXPECT_LT(error_of(r), row.tol * 1e3) << impl << " " << method << " tol " << row.tol;
  }
}

}  // namespace
}  // namespace epviz::study::peers
