#include "scene/run_palette.hpp"

#include <array>

namespace epviz::scene {

Rgba run_colour(int index, bool light_background) {
  // Sky blue, orange, bluish green, reddish purple, yellow, vermillion; on a
  // light background blue replaces the sky blue and the yellow, too pale there.
  static constexpr std::array<Rgba, 6> dark{{{0.34f, 0.71f, 0.91f, 1.0f},
                                             {0.90f, 0.62f, 0.00f, 1.0f},
                                             {0.00f, 0.62f, 0.45f, 1.0f},
                                             {0.80f, 0.47f, 0.65f, 1.0f},
                                             {0.94f, 0.89f, 0.26f, 1.0f},
                                             {0.84f, 0.37f, 0.00f, 1.0f}}};
  static constexpr std::array<Rgba, 6> light{{{0.00f, 0.45f, 0.70f, 1.0f},
                                              {0.90f, 0.62f, 0.00f, 1.0f},
                                              {0.00f, 0.62f, 0.45f, 1.0f},
                                              {0.80f, 0.47f, 0.65f, 1.0f},
                                              {0.84f, 0.37f, 0.00f, 1.0f},
                                              {0.35f, 0.35f, 0.35f, 1.0f}}};
  const auto& p = light_background ? light : dark;
  return p[std::size_t(index < 0 ? 0 : index) % p.size()];
}

}  // namespace epviz::scene
