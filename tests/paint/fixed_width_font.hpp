#pragma once
// A stand-in for the font in tests of the small charts' layouts: 7 px per
// character (UTF-8 sequence), 13 px tall, so that sizes are known exactly.
#include <string>

#include <glm/vec2.hpp>

namespace epviz::testing {

inline glm::vec2 fixed_width_measure(const std::string& text) {
  int chars = 0;
  for (unsigned char c : text) chars += (c & 0xC0) != 0x80;
  return {7.0f * float(chars), 13.0f};
}

}  // namespace epviz::testing
