#pragma once
// One user input as plain data, the way a browser page (or a recording of one)
// reports it: positions in frame pixels, keys by their DOM `KeyboardEvent.key`
// names. No GL and no ImGui here: the server parses these from the wire and
// the GUI adapter (gui_input.hpp) feeds them to ImGui, so a recorded stream
// replays exactly what a user did.
#include <cstdint>
#include <string>

namespace epviz::render {

struct InputEvent {
  enum class Kind {
    mouse_move,    // x, y
    mouse_button,  // x, y, button, down
    wheel,         // x, y, wheel_x, wheel_y
    key,           // key, down, modifiers
    text,          // text: characters typed (UTF-8), after the key's down event
    focus,         // down: the page gained (true) or lost (false) focus
  };
  Kind kind = Kind::mouse_move;
  float x = 0.0f, y = 0.0f;  // frame pixels, origin at the top-left corner
  int button = 0;            // 0 left, 1 right, 2 middle
  bool down = false;
  float wheel_x = 0.0f, wheel_y = 0.0f;  // in notches; positive: up / right (ImGui's sign)
  std::string key;                       // "a", "Enter", "ArrowLeft", " ", "Control", ...
  bool ctrl = false, shift = false, alt = false, super = false;
  std::string text;
  std::uint64_t seq = 0;  // the client's sequence number (for latency), 0 if none
};

}  // namespace epviz::render
