#include "scene/section_panel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "physics/format.hpp"
#include "physics/level_set.hpp"
#include "sim/section_chart_inverse.hpp"

namespace epviz::scene {
namespace {

Eigen::Vector2d plotted(const sim::Crossing& c, const std::array<sim::StateComponent, 2>& coords) {
  return {sim::value_of(coords[0], c.omega, c.gamma), sim::value_of(coords[1], c.omega, c.gamma)};
}

// [lo, hi] widened by `margin` of its span on each side, so that no dot
// sits on the frame; a span of (nearly) nothing gets a unit's width about its centre.
void pad(double& lo, double& hi, double margin = 0.08) {
  const double span = hi - lo;
  if (!(span > 1e-9 * std::max(1.0, std::abs(lo) + std::abs(hi)))) {
    const double mid = 0.5 * (lo + hi);
    lo = mid - 0.5;
    hi = mid + 0.5;
    return;
  }
  lo -= margin * span;
  hi += margin * span;
}

// The margin of a range fitted to the crossings: the axis titles sit in the
// plot's top-left and bottom-right corners on the panel's background, and
// few dots (one sheet of a run may hold two) put one in a corner, which 8 %
// (21 px of a 1280x720 frame's plot) left under the title.
constexpr double kFittedMargin = 0.15;

}  // namespace

std::string section_title(const sim::SectionSurface& surface,
                          const std::optional<SectionSheet>& sheet) {
  std::string s(sim::symbol(surface.function));
  s += " = ";
  s += physics::detail::num(surface.value);
  s += ", ";
  s += sim::name(surface.direction);
  if (sheet) s += ", " + sheet_name(*sheet);
  return s;
}

SectionCrossings::SectionCrossings(const SectionPanelSettings& settings,
                                   std::vector<std::vector<sim::Crossing>> crossings)
    : settings_(settings), crossings_(std::move(crossings)) {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  // The axes fit the crossings drawn: those of the sheet shown.
  for (const auto& run : crossings_) {
    for (const auto& c : run) {
      if (!on_sheet(settings.sheet, c.omega, c.gamma)) continue;
      const Eigen::Vector2d p = plotted(c, settings.coords);
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
  }
  for (int k = 0; k < 2; ++k) {
    if (!(lo[k] <= hi[k])) lo[k] = hi[k] = 0.0;  // no crossing at all
    pad(lo[k], hi[k], kFittedMargin);
    range_[std::size_t(2 * k)] = lo[k];
    range_[std::size_t(2 * k + 1)] = hi[k];
  }
}

SectionPanel SectionCrossings::panel_at(double t, const std::vector<Rgba>& colours,
                                        bool light) const {
  std::vector<const std::vector<sim::Crossing>*> lists;
  for (const auto& run : crossings_) lists.push_back(&run);
  // The runs' colours as given, then each orbit's own.
  const std::size_t runs = crossings_.size() - std::min(crossings_.size(), settings_.orbits.size());
  std::vector<Rgba> all(colours.begin(),
                        colours.begin() + std::ptrdiff_t(std::min(runs, colours.size())));
  all.resize(runs, colours.empty() ? Rgba{} : colours.back());
  for (std::size_t k = 0; runs + k < crossings_.size(); ++k)
    all.push_back(section_orbit_colour(int(k), light));
  return section_panel(settings_, range_, lists, std::vector<double>(lists.size(), t), all);
}

Rgba section_orbit_colour(int index, bool light_background) {
  // Hues the runs' palette leaves out (pink, lime, lavender, coral, cyan,
  // tan, mint, magenta), light on a dark background and deep on a light one.
  static constexpr std::array<Rgba, kMaxSectionOrbits> dark{{{1.00f, 0.55f, 0.75f, 1.0f},
                                                             {0.65f, 0.90f, 0.35f, 1.0f},
                                                             {0.72f, 0.68f, 1.00f, 1.0f},
                                                             {1.00f, 0.45f, 0.40f, 1.0f},
                                                             {0.35f, 0.95f, 0.95f, 1.0f},
                                                             {0.85f, 0.72f, 0.52f, 1.0f},
                                                             {0.55f, 1.00f, 0.78f, 1.0f},
                                                             {0.95f, 0.40f, 0.95f, 1.0f}}};
  static constexpr std::array<Rgba, kMaxSectionOrbits> light{{{0.78f, 0.10f, 0.42f, 1.0f},
                                                              {0.30f, 0.52f, 0.00f, 1.0f},
                                                              {0.36f, 0.26f, 0.78f, 1.0f},
                                                              {0.75f, 0.16f, 0.10f, 1.0f},
                                                              {0.00f, 0.45f, 0.52f, 1.0f},
                                                              {0.50f, 0.34f, 0.14f, 1.0f},
                                                              {0.05f, 0.52f, 0.38f, 1.0f},
                                                              {0.62f, 0.05f, 0.62f, 1.0f}}};
  const auto i = std::size_t(std::max(index, 0) % kMaxSectionOrbits);
  return (light_background ? light : dark)[i];
}

sim::Crossing start_crossing(const physics::InitialState& start) {
  sim::Crossing c;
  c.number = 0;
  c.t = 0.0;
  c.omega = start.omega;
  c.gamma = start.gamma;
  return c;
}

SectionOrbit::SectionOrbit(sim::RunSpec run, const physics::InitialState& start,
                           const sim::SectionSurface& surface) {
  run.initial = start;
  observer_ = std::make_unique<sim::SectionObserver>(run, surface);
  trajectory_ = sim::Trajectory::start(run);
  trajectory_->observe_dense_steps([this](const sim::DenseStep& step) { observer_->step(step); });
  // It starts on the surface, where the search sees no sign change.
  crossings_.push_back(start_crossing(start));
}

SectionOrbit::~SectionOrbit() = default;

long SectionOrbit::steps() const {
  const numerics::Stats st = trajectory_->stats();
  return st.steps + st.rejected_steps;
}

void SectionOrbit::collect() {
  const auto& found = observer_->crossings();
  for (; collected_ < found.size(); ++collected_) crossings_.push_back(found[collected_]);
}

void SectionOrbit::advance_to(double t, long max_steps) {
  const long before = steps();
  const double half = 0.5 * trajectory_->spacing();
  try {
    while (!failure_ && t_ + half <= t && steps() - before < max_steps) t_ = trajectory_->next().t;
  } catch (const numerics::IntegrationError& e) {
    failure_ = e.failure();
  }
  collect();
}

std::array<double, 4> level_range(const physics::Body& body, const physics::Level& level,
                                  const std::array<sim::StateComponent, 2>& coords) {
  // The kinetic energy of a state of the level is C1 - V(gamma) <= C1 + P |r|.
  const double kinetic = std::max(0.0, level.energy + body.weight * body.com.norm());
  std::array<double, 4> range{};
  for (int k = 0; k < 2; ++k) {
    const int c = int(coords[std::size_t(k)]);
    const double reach = c >= 3 ? 1.0 : std::sqrt(2.0 * kinetic / body.inertia[c]);
    double lo = -reach, hi = reach;
    pad(lo, hi);
    range[std::size_t(2 * k)] = lo;
    range[std::size_t(2 * k + 1)] = hi;
  }
  return range;
}

SectionPanel section_panel(const SectionPanelSettings& settings, const std::array<double, 4>& range,
                           const std::vector<const std::vector<sim::Crossing>*>& crossings,
                           const std::vector<double>& t, const std::vector<Rgba>& colours) {
  SectionPanel p;
  p.title = section_title(settings.surface, settings.sheet);
  p.axes = {std::string(sim::symbol(settings.coords[0])),
            std::string(sim::symbol(settings.coords[1]))};
  p.range = range;
  p.colours = colours;
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    auto& dots = p.runs.emplace_back();
    for (const auto& c : *crossings[i]) {
      if (c.t > t[i]) break;  // in time order
      if (on_sheet(settings.sheet, c.omega, c.gamma))
        dots.push_back(plotted(c, settings.coords));
      else
        ++p.hidden;
    }
  }
  if (p.hidden > 0) {
    // The crossings left out, so that the picture says no more than it shows.
    const SectionSheet other{settings.sheet->component, -settings.sheet->sign};
    p.note = std::to_string(p.hidden) + (p.hidden == 1 ? " crossing" : " crossings") + " on " +
             sheet_name(other) + " not drawn";
  }
  return p;
}

}  // namespace epviz::scene
