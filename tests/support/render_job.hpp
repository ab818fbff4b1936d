#pragma once
// A small, fast render job for tests of `epviz render`: the Lagrange top,
// 160 x 120, PNG frames into `out`; fps x seconds frames.
#include <filesystem>

#include <nlohmann/json.hpp>

namespace epviz::test {

inline nlohmann::json small_render_job(const std::filesystem::path& out, int fps = 3,
                                       double seconds = 2.0) {
  return {{"simulation", {{"case", "lagrange"}, {"t_end", seconds}}},
          {"width", 160},
          {"height", 120},
          {"fps", fps},
          {"duration", seconds},
          {"output", {{"dir", out.string()}, {"format", "png"}}}};
}

}  // namespace epviz::test
