// The names of the overlay's places, as a job's "overlay_place" gives them
// (scene/frame.hpp): a file of its own, so that the job reader (and its fuzz
// target) need not take the layout along.
#include <string_view>
#include <utility>

#include "scene/frame.hpp"

namespace epviz::scene {

namespace {
constexpr std::pair<OverlayPlace, std::string_view> kOverlayPlaceNames[] = {
    {OverlayPlace::automatic, "auto"},          {OverlayPlace::beside, "beside"},
    {OverlayPlace::top_left, "top-left"},       {OverlayPlace::top_right, "top-right"},
    {OverlayPlace::bottom_left, "bottom-left"}, {OverlayPlace::bottom_right, "bottom-right"}};
}  // namespace

std::string_view name(OverlayPlace place) {
  for (const auto& [p, n] : kOverlayPlaceNames)
    if (p == place) return n;
  return "auto";
}

std::optional<OverlayPlace> overlay_place_from_name(std::string_view text) {
  for (const auto& [p, n] : kOverlayPlaceNames)
    if (n == text) return p;
  return std::nullopt;
}

}  // namespace epviz::scene
