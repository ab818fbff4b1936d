#include "section/section_coords.hpp"

#include <array>
#include <utility>

#include "physics/andoyer.hpp"

namespace epviz::section {
namespace {

constexpr std::array<std::pair<AndoyerCoord, std::pair<std::string_view, std::string_view>>, 5>
    kAndoyer{{
        {AndoyerCoord::l, {"andoyer_l", "l"}},
        {AndoyerCoord::g, {"andoyer_g", "g"}},
        {AndoyerCoord::L, {"andoyer_L", "L"}},
        {AndoyerCoord::G, {"andoyer_G", "G"}},
        {AndoyerCoord::L_over_G, {"andoyer_L_over_G", "L/G"}},
    }};

}  // namespace

const std::vector<PlotCoord>& all_plot_coords() {
  static const std::vector<PlotCoord> all = [] {
    std::vector<PlotCoord> v(sim::all_state_components().begin(),
                             sim::all_state_components().end());
    for (const auto& [a, names] : kAndoyer) v.emplace_back(a);
    return v;
  }();
  return all;
}

std::string_view name(const PlotCoord& c) {
  return c.andoyer ? kAndoyer[std::size_t(*c.andoyer)].second.first : sim::name(c.component);
}

std::string_view symbol(const PlotCoord& c) {
  return c.andoyer ? kAndoyer[std::size_t(*c.andoyer)].second.second : sim::symbol(c.component);
}

std::optional<PlotCoord> plot_coord_from_name(std::string_view s) {
  for (const PlotCoord& c : all_plot_coords())
    if (name(c) == s) return c;
  return std::nullopt;
}

bool is_andoyer(const PlotCoord& c) { return c.andoyer.has_value(); }

std::optional<double> value_of(const PlotCoord& c, const physics::Body& body,
                               const physics::Vector3d& omega, const physics::Vector3d& gamma) {
  if (!c.andoyer) return sim::value_of(c.component, omega, gamma);
  const auto a = physics::andoyer_variables(body, omega, gamma);
  switch (*c.andoyer) {
    case AndoyerCoord::l: return a.l;
    case AndoyerCoord::g: return a.g;
    case AndoyerCoord::L: return a.L;
    case AndoyerCoord::G: return a.G;
    case AndoyerCoord::L_over_G:
      if (!(a.G > 0.0)) return std::nullopt;
      return a.L / a.G;
  }
  return std::nullopt;
}

}  // namespace epviz::section
