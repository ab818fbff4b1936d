#include "app/cases_command.hpp"

#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "io/json_text.hpp"
#include "physics/cases.hpp"
#include "physics/format.hpp"

namespace epviz::app {
namespace {

std::string vec(const Eigen::Vector3d& v) { return physics::detail::vec(v, 6); }

nlohmann::json to_json(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }

int list_cases(bool json) {
  if (json) {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& p : physics::case_presets())
      all.push_back({{"name", p.name},
                     {"summary", p.summary},
                     {"conditions", p.conditions},
                     {"extra_integral", p.extra_integral},
                     {"inertia", to_json(p.body.inertia)},
                     {"com", to_json(p.body.com)},
                     {"weight", p.body.weight},
                     {"omega", to_json(p.initial.omega)},
                     {"gamma", to_json(p.initial.gamma)}});
    std::printf("%s\n", io::json_text(all, 2).c_str());
    return 0;
  }
  for (const auto& p : physics::case_presets()) {
    std::printf("%s\n  %s\n", p.name.c_str(), p.summary.c_str());
    std::printf("  conditions:     %s\n", p.conditions.c_str());
    std::printf("  4th integral:   %s\n",
                p.extra_integral.empty() ? "none" : p.extra_integral.c_str());
    std::printf("  inertia %s  com %s  weight %.6g\n", vec(p.body.inertia).c_str(),
                vec(p.body.com).c_str(), p.body.weight);
    std::printf("  omega0  %s  gamma0 %s\n\n", vec(p.initial.omega).c_str(),
                vec(p.initial.gamma).c_str());
  }
  return 0;
}

}  // namespace

std::function<int()> add_cases_command(cli::Command app) {
  auto json = std::make_shared<bool>(false);
  cli::Command cmd = app.add_subcommand("cases", "List the classical cases and their presets");
  cmd.add_flag("--json", *json, "print as JSON");
  return [json] { return list_cases(*json); };
}

}  // namespace epviz::app
