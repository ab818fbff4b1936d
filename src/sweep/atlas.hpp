#pragma once
// Atlas figures of a finished sweep: a metric of its rows as a heat map over
// two of its axes. The metric is a row key ("ftle", "reference_error",
// "cpu_seconds", "steps"), a path into one ("max_relative_drift.energy",
// "failure.t"), "time_to_failure" (the failure's time, t_end without one),
// or "largest_stable:AXIS" (the largest value of AXIS among the cell's points
// that did not fail: the largest stable step of a method at an energy). Axes
// that are neither x, y nor reduced give one figure per combination of their values.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "chart/chart_spec.hpp"
#include "io/bad_input.hpp"
#include "sweep/self_check.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {

class AtlasError : public io::BadInput {
 public:
  using io::BadInput::BadInput;
};

// The heat map's columns are the x axis's values left to right, its rows the
// y axis's top to bottom (chart::HeatMapSpec's order). A numeric axis
// ascends whatever the sweep's order: x to the right, y upwards (its largest
// value in the first row); an axis of names (methods) keeps the sweep's
// order, the first name in the first row (at the top) and column.
struct AtlasFigure {
  std::string file_name;  // "atlas_ftle_gamma0_gamma1.png", made safe for file systems
  chart::HeatMapSpec heat_map;
};

// "metric:x:y" (the --atlas option). Throws AtlasError naming --atlas.
AtlasRequest parse_atlas_option(const std::string& text);

// Throws AtlasError when `request` cannot be drawn from `rows` (any order):
// no rows, an axis that is not in them or a metric that no row has. The
// merge asks this of every atlas before it writes anything.
void check_atlas_request(const std::vector<nlohmann::json>& rows, const AtlasRequest& request);

// `rows`: the sweep's rows (any order). Throws AtlasError for an axis that
// is not in the rows or a metric that no row has. Axes are titled by their
// symbols and numeric ones carry their values (round ticks); the note under
// the map is the caption of sweep/atlas_labels.hpp, whose FTLE window and
// separation come from `ftle` (the sweep file's settings: the rows lack them);
// the title ends with `check`'s verdict on the metric (sweep/self_check.hpp).
std::vector<AtlasFigure> atlas_figures(const std::vector<nlohmann::json>& rows,
                                       const AtlasRequest& request,
                                       const std::optional<FtleSettings>& ftle = std::nullopt,
                                       const SelfCheck* check = nullptr);

// The figures of every request, each map with the others as its margin
// peers (chart::HeatMapSpec::margin_peers): all maps of one sweep come out
// with one plot rectangle, whatever their colour bars' labels and keys, so
// that they compare side by side. (atlas_figures does this among the
// figures of its one request.)
std::vector<AtlasFigure> atlas_figure_set(const std::vector<nlohmann::json>& rows,
                                          const std::vector<AtlasRequest>& requests,
                                          const std::optional<FtleSettings>& ftle = std::nullopt,
                                          const SelfCheck* check = nullptr);

}  // namespace epviz::sweep
