#include "peers/scipy_peer.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace epviz::peers {
namespace {

constexpr const char* kPython = "/usr/bin/python3";

struct ProcessOutput {
  int exit_code = -1;
  std::string out, err;
};

// Runs argv with `input` on stdin; collects stdout and stderr (polled, so that
// neither pipe can fill up and block the child).
ProcessOutput run_process(const std::vector<std::string>& argv, const std::string& input) {
  int in[2], out[2], err[2];
  if (pipe(in) || pipe(out) || pipe(err)) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, in[0], 0);
  posix_spawn_file_actions_adddup2(&fa, out[1], 1);
  posix_spawn_file_actions_adddup2(&fa, err[1], 2);
  for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]}) posix_spawn_file_actions_addclose(&fa, fd);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, args[0], &fa, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  close(in[0]);
  close(out[1]);
  close(err[1]);
  if (rc != 0) {
    close(in[1]);
    close(out[0]);
    close(err[0]);
    throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(rc));
  }
  // The problem is a few hundred bytes: far below the pipe's capacity.
  std::size_t written = 0;
  while (written < input.size()) {
    const ssize_t n = write(in[1], input.data() + written, input.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    written += std::size_t(n);
  }
  close(in[1]);
  ProcessOutput po;
  pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
  std::string* sinks[2] = {&po.out, &po.err};
  int open_fds = 2;
  char buf[4096];
  while (open_fds > 0) {
    if (poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = read(fds[i].fd, buf, sizeof buf);
      if (n > 0) {
        sinks[i]->append(buf, std::size_t(n));
      } else if (n == 0 || errno != EINTR) {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  po.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  return po;
}

ScipyResults all_with(std::size_t n, const std::string& status, const std::string& reason) {
  PeerResult r;
  r.status = status;
  r.reason = reason;
  return {std::vector<PeerResult>(n, r), std::vector<PeerResult>(n, r)};
}

nlohmann::json vec(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

}  // namespace

std::string scipy_driver_path() {
  if (const char* env = std::getenv("EPVIZ_SCIPY_DRIVER"); env && *env) return env;
  // This file is src/peers/scipy_peer.cpp of the source tree (CMake compiles by absolute path).
  const std::filesystem::path here(__FILE__);
  return (here.parent_path().parent_path().parent_path() / "bench" / "peers" / "scipy_driver.py").string();
}

ScipyResults run_scipy_peers(const physics::Body& body, const physics::InitialState& initial,
                             double t_end, const std::vector<double>& tolerances, int repeats) {
  const std::size_t n = tolerances.size();
  if (access(kPython, X_OK) != 0) return all_with(n, "skipped", std::string(kPython) + " not found");
  const std::string script = scipy_driver_path();
  if (!std::filesystem::exists(script)) return all_with(n, "skipped", "SciPy driver not found: " + script);
  nlohmann::json problem = {
      {"inertia", vec(body.inertia)}, {"com", vec(body.com)},       {"weight", body.weight},
      {"omega0", vec(initial.omega)}, {"gamma0", vec(initial.gamma)}, {"t_end", t_end},
      {"tolerances", tolerances},     {"repeats", std::max(repeats, 1)}};
  ProcessOutput po;
  try {
    po = run_process({kPython, script}, problem.dump());
  } catch (const std::exception& e) {
    return all_with(n, "skipped", e.what());
  }
  auto tail = [](const std::string& s) { return s.size() > 400 ? s.substr(s.size() - 400) : s; };
  if (po.exit_code != 0)
    return all_with(n, "failed", "scipy driver exited with " + std::to_string(po.exit_code) + ": " + tail(po.err));
  nlohmann::json reply;
  try {
    reply = nlohmann::json::parse(po.out);
  } catch (const std::exception& e) {
    return all_with(n, "failed", std::string("scipy driver wrote no JSON: ") + e.what() + " " + tail(po.err));
  }
  if (reply.contains("skipped")) return all_with(n, "skipped", reply["skipped"].get<std::string>());
  ScipyResults out = all_with(n, "failed", "no result from the scipy driver");
  for (const auto& r : reply.at("results")) {
    const double tol = r.at("tol").get<double>();
    std::size_t i = 0;
    while (i < n && tolerances[i] != tol) ++i;
    if (i == n) continue;
    PeerResult p;
    p.status = r.value("status", std::string("failed"));
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
    if (method == "dop853-solve_ivp") out.solve_ivp[i] = p;
    else if (method == "dop853-ode") out.ode[i] = p;
  }
  return out;
}

}  // namespace epviz::peers
