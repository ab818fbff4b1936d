#include "study/peers/scipy_peer.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/data_dir.hpp"
#include "io/json_text.hpp"
#include "io/subprocess.hpp"

namespace epviz::study::peers {
namespace {

constexpr const char* kPython = "/usr/bin/python3";

ScipyResults all_with(std::size_t n, PeerStatus status, const std::string& reason) {
  PeerResult r;
  r.status = status;
  r.reason = reason;
  return {std::vector<PeerResult>(n, r), std::vector<PeerResult>(n, r)};
}

nlohmann::json vec(const Eigen::Vector3d& v) {
  return nlohmann::json::array({v.x(), v.y(), v.z()});
}

}  // namespace

std::string scipy_driver_path() {
  if (const char* env = std::getenv("EPVIZ_SCIPY_DRIVER"); env && *env) return env;
  // Installed as share/epviz/bench/peers/, in the source tree as bench/peers/.
  return io::find_data_path("bench/peers/scipy_driver.py").string();
}

ScipyResults run_scipy_peers(const physics::Body& body, const physics::InitialState& initial,
                             double t_end, const std::vector<double>& tolerances, int repeats) {
  const std::size_t n = tolerances.size();
  if (access(kPython, X_OK) != 0)
    return all_with(n, PeerStatus::skipped, std::string(kPython) + " not found");
  const std::string script = scipy_driver_path();
  if (script.empty() || !std::filesystem::exists(script))
    return all_with(
        n, PeerStatus::skipped,
        "SciPy driver not found: " +
            (script.empty() ? "bench/peers/scipy_driver.py in the data directories" : script));
  nlohmann::json problem = {{"inertia", vec(body.inertia)}, {"com", vec(body.com)},
                            {"weight", body.weight},        {"omega0", vec(initial.omega)},
                            {"gamma0", vec(initial.gamma)}, {"t_end", t_end},
                            {"tolerances", tolerances},     {"repeats", std::max(repeats, 1)}};
  io::ProcessOutput po;
  try {
    po = io::run_process({kPython, script}, io::json_text(problem));
  } catch (const std::exception& e) {
    return all_with(n, PeerStatus::skipped, e.what());
  }
  auto tail = [](const std::string& s) { return s.size() > 400 ? s.substr(s.size() - 400) : s; };
  if (!po.status.success())
    return all_with(n, PeerStatus::failed,
                    "scipy driver " + po.status.describe() + ": " + tail(po.err));
  nlohmann::json reply;
  try {
    reply = io::parse_json(po.out);
  } catch (const std::exception& e) {
    return all_with(n, PeerStatus::failed,
                    std::string("scipy driver wrote no JSON: ") + e.what() + " " + tail(po.err));
  }
  if (reply.contains("skipped"))
    return all_with(n, PeerStatus::skipped, reply["skipped"].get<std::string>());
  ScipyResults out = all_with(n, PeerStatus::failed, "no result from the scipy driver");
  for (const auto& r : reply.at("results")) {
    const double tol = r.at("tol").get<double>();
    std::size_t i = 0;
    while (i < n && tolerances[i] != tol) ++i;
    if (i == n) continue;
    PeerResult p;
    p.status =
        r.value("status", std::string("failed")) == "ok" ? PeerStatus::ok : PeerStatus::failed;
    p.reason = r.value("reason", std::string());
    if (r.contains("omega")) {
      const auto w = r["omega"].get<std::vector<double>>();
      const auto g = r["gamma"].get<std::vector<double>>();
      p.omega = Eigen::Vector3d(w[0], w[1], w[2]);
      p.gamma = Eigen::Vector3d(g[0], g[1], g[2]);
      p.t = r.value("t", 0.0);
      p.rhs_evals = r.value("nfev", 0L);
      p.steps = r.value("steps", -1L);
      p.cpu_seconds = r.value("cpu_seconds", 0.0);
      p.repeats = r.value("repeats", 0);
    }
    const std::string method = r.value("method", std::string());
    if (method == "dop853-solve_ivp")
      out.solve_ivp[i] = p;
    else if (method == "dop853-ode")
      out.ode[i] = p;
  }
  return out;
}

}  // namespace epviz::study::peers
