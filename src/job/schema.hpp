#pragma once
// The render-job format in one place: every key with its type, default,
// allowed values and help, read strictly (an unknown key is an error naming
// the file and the key path) and written back, so that what `epviz serve`
// saves is what `epviz render` reads.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "io/json_reader.hpp"
#include "job/document.hpp"
#include "job/fields.hpp"

namespace epviz::job {

enum class ValueType { boolean, integer, number, text, choice, vec3, colour, object };

struct KeyInfo {
  std::string path;  // "camera.azimuth"
  ValueType type;
  std::string default_value;  // as a job would write it; empty where there is none
  std::string allowed;        // "body, space", "16 to 8192", ...
  std::string help;
};

inline constexpr double min_plane_extent = 0.01, max_plane_extent = 1000.0;
inline constexpr double min_camera_distance = 1.2;  // exclusive: the camera would be inside
inline constexpr double max_camera_distance = 100.0;

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
