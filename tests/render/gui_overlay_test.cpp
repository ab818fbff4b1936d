// An overlay's ImGui context is current only while it draws or measures:
// making and dropping overlays never leaves ImGui's current context pointing
// at a freed one (the next context made would count an allocation in it, a
// write to freed memory).
#include <gtest/gtest.h>

#include <imgui.h>

#include "render/gui_overlay.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;

render::OverlayOptions builtin_font() {
  render::OverlayOptions o;
  o.builtin_font = true;
  return o;
}

TEST(ImGuiOverlay, NoneLeavesItsContextCurrent) {
  et::shared_gl_context().make_current();
  ImGuiContext* const before = ImGui::GetCurrentContext();
  {
    render::ImGuiOverlay first(builtin_font());
    EXPECT_EQ(ImGui::GetCurrentContext(), before);
    (void)first.label_font_px();  // measures in its own context
    EXPECT_EQ(ImGui::GetCurrentContext(), before);
  }
  EXPECT_EQ(ImGui::GetCurrentContext(), before);
}

TEST(ImGuiOverlay, AnotherContextStaysCurrentThroughOnesLife) {
  et::shared_gl_context().make_current();
  ImGuiContext* const before = ImGui::GetCurrentContext();
  ImGuiContext* other = ImGui::CreateContext();
  ImGui::SetCurrentContext(other);
  { render::ImGuiOverlay overlay(builtin_font()); }
  EXPECT_EQ(ImGui::GetCurrentContext(), other);
  ImGui::DestroyContext(other);
  ImGui::SetCurrentContext(before);
}

}  // namespace
}  // namespace epviz
