#pragma once
// The trail's time colouring, shared by the sphere's trail, the plane's path
// and the colour bar that explains them: age 0 is now, 1 the oldest point kept.
#include <glm/vec4.hpp>

#include "render/colour_map.hpp"

namespace epviz::paint {

inline const render::ColourMap& time_map() {
  static const render::ColourMap map = render::ColourMap::time();
  return map;
}
// Newest points bright and opaque, old ones darker and fading to
// `oldest_alpha`; the map's top is cut where the theme's background would
// swallow it (scene::Theme::trail_map_top, trail_oldest_alpha).
inline glm::vec4 age_colour(float age, float top, float oldest_alpha) {
  return time_map()((1.0f - age) * top, oldest_alpha + (1.0f - oldest_alpha) * (1.0f - age));
}
// The same hue, opaque: the colour bar's.
inline glm::vec4 age_colour_opaque(float age, float top) {
  return time_map()((1.0f - age) * top, 1.0f);
}

}  // namespace epviz::paint
