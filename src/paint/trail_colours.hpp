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
// Newest points bright and opaque, old ones darker and fading out; the map's
// top is cut where the theme's background would swallow it.
inline glm::vec4 age_colour(float age, float top) {
  return time_map()((1.0f - age) * top, 0.25f + 0.75f * (1.0f - age));
}
// The same hue, opaque: the colour bar's.
inline glm::vec4 age_colour_opaque(float age, float top) {
  return time_map()((1.0f - age) * top, 1.0f);
}

}  // namespace epviz::paint
