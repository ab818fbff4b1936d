#include "render/gui_input.hpp"

#include <imgui.h>

#include "render/imgui_context_scope.hpp"

#include <bitset>
#include <cctype>
#include <utility>

namespace epviz::render {
namespace {

// Named keys live above the character range of io.KeysDown[512].
constexpr int kNamedBase = 256;

struct NamedKey {
  const char* dom;
  ImGuiKey_ key;
};
constexpr NamedKey kNamedKeys[] = {
    {"Tab", ImGuiKey_Tab},
    {"ArrowLeft", ImGuiKey_LeftArrow},
    {"ArrowRight", ImGuiKey_RightArrow},
    {"ArrowUp", ImGuiKey_UpArrow},
    {"ArrowDown", ImGuiKey_DownArrow},
    {"PageUp", ImGuiKey_PageUp},
    {"PageDown", ImGuiKey_PageDown},
    {"Home", ImGuiKey_Home},
    {"End", ImGuiKey_End},
    {"Insert", ImGuiKey_Insert},
    {"Delete", ImGuiKey_Delete},
    {"Backspace", ImGuiKey_Backspace},
    {" ", ImGuiKey_Space},
    {"Enter", ImGuiKey_Enter},
    {"Escape", ImGuiKey_Escape},
};

void set_modifiers(ImGuiIO& io, const InputEvent& e) {
  io.KeyCtrl = e.ctrl;
  io.KeyShift = e.shift;
  io.KeyAlt = e.alt;
  io.KeySuper = e.super;
}

}  // namespace

int gui_key_index(const std::string& dom_key) {
  for (const auto& k : kNamedKeys)
    if (dom_key == k.dom) return kNamedBase + k.key;
  // Letters for the text-editing shortcuts (Ctrl+A, C, V, X, Y, Z): one index per letter.
  if (dom_key.size() == 1 && std::isalpha(static_cast<unsigned char>(dom_key[0])))
    return std::toupper(static_cast<unsigned char>(dom_key[0]));
  return -1;
}

void GuiInput::configure(ImGuiContext* context) {
  ImGuiContextScope scope(context);
  ImGuiIO& io = ImGui::GetIO();
  for (const auto& k : kNamedKeys) io.KeyMap[k.key] = kNamedBase + k.key;
  io.KeyMap[ImGuiKey_KeyPadEnter] = kNamedBase + ImGuiKey_Enter;
  io.KeyMap[ImGuiKey_A] = 'A';
  io.KeyMap[ImGuiKey_C] = 'C';
  io.KeyMap[ImGuiKey_V] = 'V';
  io.KeyMap[ImGuiKey_X] = 'X';
  io.KeyMap[ImGuiKey_Y] = 'Y';
  io.KeyMap[ImGuiKey_Z] = 'Z';
}

void GuiInput::push(InputEvent event) { queue_.push_back(std::move(event)); }

void GuiInput::rescale(float sx, float sy) {
  for (InputEvent& e : queue_) {
    if (e.kind != InputEvent::Kind::mouse_move && e.kind != InputEvent::Kind::mouse_button &&
        e.kind != InputEvent::Kind::wheel)
      continue;
    e.x *= sx;
    e.y *= sy;
  }
}

namespace {

// What has changed during the frame being filled.
struct FrameChanges {
  std::bitset<8> buttons;
  std::bitset<512> keys;
  bool moved = false;
};

bool any_button_held(const ImGuiIO& io) {
  for (bool down : io.MouseDown)
    if (down) return true;
  return false;
}

bool fits_this_frame(const InputEvent& e, const FrameChanges& changed, const ImGuiIO& io) {
  switch (e.kind) {
    case InputEvent::Kind::mouse_move:
    case InputEvent::Kind::wheel:
      // After a press or release in this frame, ImGui would see that button
      // change at the new place: the move waits for the next frame.
      return changed.buttons.none();
    case InputEvent::Kind::mouse_button:
      if (e.button < 0 || e.button >= 5) return true;
      // A release in the frame the pointer moved would end a drag before
      // ImGui saw the movement.
      return !changed.buttons[std::size_t(e.button)] && !(changed.moved && any_button_held(io));
    case InputEvent::Kind::key: {
      const int index = gui_key_index(e.key);
      return index < 0 || !changed.keys[std::size_t(index)];
    }
    case InputEvent::Kind::text:
    case InputEvent::Kind::focus: return true;
  }
  return true;
}

void apply_one(ImGuiIO& io, const InputEvent& e, FrameChanges& changed) {
  switch (e.kind) {
    case InputEvent::Kind::mouse_move:
      io.MousePos = ImVec2(e.x, e.y);
      changed.moved = true;
      break;
    case InputEvent::Kind::mouse_button:
      if (e.button < 0 || e.button >= 5) break;  // buttons ImGui does not track
      io.MousePos = ImVec2(e.x, e.y);
      io.MouseDown[e.button] = e.down;
      changed.buttons.set(std::size_t(e.button));
      break;
    case InputEvent::Kind::wheel:
      io.MousePos = ImVec2(e.x, e.y);
      io.MouseWheel += e.wheel_y;
      io.MouseWheelH += e.wheel_x;
      break;
    case InputEvent::Kind::key: {
      set_modifiers(io, e);
      const int index = gui_key_index(e.key);
      // The page sends what the browser pastes as text; ImGui's Ctrl+V would
      // paste its own in-process clipboard a second time.
      if (index < 0 || (index == 'V' && (e.ctrl || e.super))) break;
      io.KeysDown[index] = e.down;
      changed.keys.set(std::size_t(index));
      break;
    }
    case InputEvent::Kind::text: io.AddInputCharactersUTF8(e.text.c_str()); break;
    case InputEvent::Kind::focus: io.AddFocusEvent(e.down); break;
  }
}

}  // namespace

void GuiInput::apply(ImGuiContext* context, const std::function<void(const InputEvent&)>& observe,
                     float layout_scale) {
  ImGuiContextScope scope(context);
  ImGuiIO& io = ImGui::GetIO();
  // The wheel is an amount per frame, not a state.
  io.MouseWheel = 0.0f;
  io.MouseWheelH = 0.0f;
  FrameChanges changed;
  while (!queue_.empty() && fits_this_frame(queue_.front(), changed, io)) {
    const InputEvent e = std::move(queue_.front());
    queue_.pop_front();
    InputEvent in_layout = e;
    in_layout.x /= layout_scale;
    in_layout.y /= layout_scale;
    apply_one(io, in_layout, changed);
    if (observe) observe(e);
  }
}

}  // namespace epviz::render
