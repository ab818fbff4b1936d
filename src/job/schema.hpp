#pragma once
// The render-job format in one place: every key with its type, default,
// allowed values and help, read strictly (an unknown key is an error naming
// the file and the key path) and written back, so that what `epviz serve`
// saves is what `epviz render` reads.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json_reader.hpp"
#include "job/document.hpp"

namespace epviz::job {

enum class ValueType { boolean, integer, number, text, choice, vec3, colour, object };

struct KeyInfo {
  std::string path;  // "camera.azimuth"
  ValueType type;
  std::string default_value;  // as a job would write it; empty where there is none
  std::string allowed;        // "body, space", "16 to 8192", ...
  std::string help;
};

// Bounds on numbers a job (or `epviz simulate`) may give beyond their type:
// wide enough for any unit system, narrow enough that energies, steps and
// the drawn body's proportions stay finite in double and float arithmetic.
inline constexpr long max_samples = 100'000'000;
inline constexpr double min_moment = 1e-6, max_moment = 1e6;  // each principal moment
inline constexpr double max_magnitude = 1e6;  // each component of com, omega, gamma; weight
inline constexpr double min_plane_extent = 0.01, max_plane_extent = 1000.0;
inline constexpr double min_camera_distance = 1.2;  // exclusive: the camera would be inside
inline constexpr double max_camera_distance = 100.0;

// A bound as messages and the keys' table write it: "1e-6", "0.01", "1000".
std::string format_number(double value);

// Every key of a single render job, in the order a job is written.
std::vector<KeyInfo> render_job_keys();

// The keys of a "simulation" object (read into `fields`, origins naming the
// file and key); the caller calls finish(). With `auto_tol` (render jobs)
// "tol": "auto" is accepted and reported there.
SimulationFields read_simulation_fields(io::ObjectReader& reader, bool* auto_tol = nullptr);

// A single render job from its JSON object; throws io::BadInput naming
// `file` and the key path. The output name stays empty when not given.
JobDocument read_job(const nlohmann::json& object, const std::string& file);

// The job as JSON that read_job accepts: every scene key, and the simulation
// and output keys that are given.
nlohmann::ordered_json write_job(const JobDocument& job);

// "#rrggbbaa".
std::string hex_colour(const scene::Rgba& colour);

}  // namespace epviz::job
