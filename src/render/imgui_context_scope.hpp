#pragma once
// Makes an ImGui context current for a scope and restores the previous one,
// so that several ImGui contexts (an overlay per painter, one per browser
// tab) can live on one thread.
#include <imgui.h>

namespace epviz::render {

class ImGuiContextScope {
 public:
  explicit ImGuiContextScope(ImGuiContext* context) : previous_(ImGui::GetCurrentContext()) {
    ImGui::SetCurrentContext(context);
  }
  ~ImGuiContextScope() { ImGui::SetCurrentContext(previous_); }
  ImGuiContextScope(const ImGuiContextScope&) = delete;
  ImGuiContextScope& operator=(const ImGuiContextScope&) = delete;

 private:
  ImGuiContext* previous_;
};

}  // namespace epviz::render
