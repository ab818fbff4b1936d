#pragma once
// The platform adapter between input events (input_event.hpp) and ImGui.
// Debian's Dear ImGui is 1.86, whose input is state (io.MousePos,
// io.MouseDown[], io.KeysDown[]) read once per frame, not a queue of events:
// a click whose press and release arrive between two frames would vanish. So
// events wait here and are applied in order, a frame at a time, stopping
// before an event that would change a button or key already changed in this
// frame, or release a button after the pointer moved in it (the "trickle"
// ImGui 1.87+ does itself).
#include <deque>
#include <functional>

#include "render/input_event.hpp"

struct ImGuiContext;

namespace epviz::render {

class GuiInput {
 public:
  // Sets the context's key map for the keys this adapter reports. Call once per context.
  static void configure(ImGuiContext* context);

  void push(InputEvent event);
  bool pending() const { return !queue_.empty(); }
  // The view was resized by (sx, sy): events still waiting were given in the
  // old size's pixels, and a click that waits for the next frame must land
  // on the same control after the resize (adaptive resolution resizes a
  // view between frames).
  void rescale(float sx, float sy);
  std::size_t queued() const { return queue_.size(); }

  // Applies the events that fit into the next frame to the context's io
  // (call before its NewFrame) and passes each one applied to `observe`, in
  // order, with the context current (the application's own shortcuts and
  // camera drags, which may read ImGui::GetIO()).
  // Positions are divided by `layout_scale` for ImGui (the overlay's
  // framebuffer scale); `observe` gets them as given.
  void apply(ImGuiContext* context, const std::function<void(const InputEvent&)>& observe = {},
             float layout_scale = 1.0f);

 private:
  std::deque<InputEvent> queue_;
};

// The io.KeysDown index for a DOM key name, or -1 for keys ImGui has no use for.
int gui_key_index(const std::string& dom_key);

}  // namespace epviz::render
