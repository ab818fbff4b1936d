#pragma once
// λ(T), the finite-time Lyapunov exponent over the first T of a run, for the
// points of a sweep that asked for it ("ftle": {"curve": true}): how the
// exponent converges with the time. A chaotic orbit's λ(T) levels off at its
// exponent; a regular orbit's falls towards 0 like ln T / T, since its
// neighbours part only linearly (docs/cluster.md, "FTLE").
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "chart/chart_spec.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {

// One line per row that has an `ftle_curve`, named by its axis values, on
// log axes (λ <= 0 breaks its line there and is marked in a row "λ ≤ 0"
// under the plot, with a note counting such points), and a dashed guide
// c · ln T / T through the lowest line's last point. nullopt when no row has
// a curve. The file name is "ftle_curves.png".
// What is wrong with a row's `ftle_curve` ("" when it has none or a lawful
// one): [[T, λ], ...] with T a positive number and λ a number or null (a
// value that was not finite), as "key 'ftle_curve': ...". Rows come from
// shard files, which anyone may edit: the merge checks them with this before
// ftle_curve_figure reads them.
std::string ftle_curve_problem(const nlohmann::json& row);

std::optional<chart::Figure> ftle_curve_figure(const std::vector<nlohmann::json>& rows,
                                               const std::optional<FtleSettings>& ftle);

}  // namespace epviz::sweep
