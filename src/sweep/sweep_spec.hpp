#pragma once
// A parameter sweep as its file states it (render_jobs/*.sweep.json): a base
// "simulation" object, read by the render job's own reader (job/schema.hpp),
// and "axes", each naming one simulation field and the values it takes. The
// points are the cartesian product of the axes, numbered 0..N-1 with the
// first axis varying slowest. Read strictly: an unknown key or a value of the
// wrong kind is an io::BadInput naming the file and the key path.
//
//   {"simulation": {"case": "generic", "t_end": 50},
//    "axes": [{"field": "method", "values": ["rk4", "gauss4"]},
//             {"field": "step", "from": 0.001, "to": 0.5, "count": 24, "scale": "log"}],
//    "reference": true, "ftle": true,
//    "atlas": [{"metric": "largest_stable:step", "x": "energy", "y": "method"}]}
#include <cstddef>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "job/document.hpp"

namespace epviz::sweep {

// Fields an axis may name: the sweepable fields of the table (job/fields.hpp)
// with their components ("inertia[0]"), "energy", the total energy C1
// reached by scaling the initial angular velocity (sweep/sweep_point.hpp),
// and "area_constant", C0: with it "energy" and "area_constant" are a level
// (C1, C0) of an energy-momentum map, whose "level_orbits" orbits start on
// the level (sweep/level_point.hpp).
inline constexpr const char* energy_axis = "energy";
inline constexpr const char* area_axis = "area_constant";
std::vector<std::string> axis_fields();
std::string axis_fields_joined();

struct Axis {
  std::string field;
  std::vector<nlohmann::json> values;  // numbers, strings or 3-vectors, as the field takes
  std::string key;                     // "axes[1]", for messages
};

// Finite-time Lyapunov exponent of each point (sweep/point_run.hpp says how).
struct FtleSettings {
  double separation = 1e-8;  // initial and renormalised distance of the two states
  double window = 0.0;       // time between renormalisations; 0: the sample spacing
  // Also λ(T), the exponent over the first k windows, at k = 1, 2, 4, … and
  // the last: how it converges with the time (rows' `ftle_curve`, merge's chart).
  bool curve = false;
};
// At most this many points may ask for λ(T) curves: merge draws them all in one chart.
inline constexpr long kMaxCurvePoints = 12;

// A heat map merge draws from the rows: `metric` over axes x and y.
struct AtlasRequest {
  std::string metric, x, y;
  // The colour bar's range; NaN: the values' own. A fixed range lets two
  // atlases (a chaotic and an integrable body) be compared by colour.
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
};

// The numbers every row holds that an atlas can draw (sweep/run_record.cpp,
// sweep/point_run.cpp write them), besides "ftle" and "reference_error"
// (rows have them when the sweep asks), "time_to_failure" and
// "largest_stable:AXIS" (sweep/atlas.hpp).
std::vector<std::string> row_metrics();

// The atlas metrics the rows of a sweep will have, for messages:
// "ftle, time_to_failure, largest_stable:AXIS (AXIS: gamma[0], ...), cpu_seconds, ...".
std::string atlas_metrics_allowed(bool reference, bool ftle, const std::vector<std::string>& axes);

// The numbers an energy-momentum map's rows hold (sweep/level_point.hpp).
std::vector<std::string> level_row_metrics();

inline constexpr int kMaxLevelOrbits = 4096;

struct SweepSpec {
  std::string file;
  job::SimulationFields base;
  std::vector<Axis> axes;
  bool reference = false;
  std::optional<FtleSettings> ftle;
  std::vector<AtlasRequest> atlases;
  // Orbits per level of an energy-momentum map; 0: the sweep is not one.
  int level_orbits = 0;
  bool levels() const { return level_orbits > 0; }
  // The self-check's limit (sweep/self_check.hpp): the largest change a
  // sampled point's metric may show at a 100x tighter tolerance, as a share of
  // the colour bar's range ("self_check": {"threshold": 0.05}).
  double self_check_threshold = 0.05;
  // Of the canonical content (the parsed JSON written with sorted keys):
  // whitespace and key order do not change it, any value does.
  std::string hash;

  long point_count() const;
  // The index into each axis's values of point `index` (first axis slowest).
  std::vector<std::size_t> coordinates(long index) const;
  // One point per value of each axis, the other axes at their first value
  // (sorted, distinct): reading these reads every value of the sweep once.
  std::vector<long> value_probes() const;
};

inline constexpr long max_points = 10'000'000;

SweepSpec read_sweep(const nlohmann::json& root, const std::string& file);
SweepSpec read_sweep_file(const std::filesystem::path& path);

}  // namespace epviz::sweep
