#pragma once
// What a render job asks of the picture, independent of the physics.
#include <optional>
#include "scene/cloud.hpp"  // the cloud

#include "scene/frame.hpp"
#include "scene/section_panel.hpp"

namespace epviz::scene {

struct SceneSettings {
  View view = View::body;
  Layers layers;
  CameraSettings camera;
  ThemeId theme = ThemeId::dark;  // colours not given by the job are the theme's
  Colours colours;
  int width = 1280;
  int height = 720;
  double fps = 30.0;
  double duration = 10.0;          // seconds of video; the run's t_end is spread over them
  double trail_length = 0.0;       // simulation time the trail covers; 0: the whole run
  float plane_extent = 2.5f;       // the Riccati panel shows [-extent, extent]^2
  bool auto_tolerance = true;      // derive the tolerance from the resolution
  bool formulation_given = false;  // the job chose the formulation itself
  std::string title;               // overrides the case's title when not empty
  int trace_axis = 3;              // space view: the body axis (1, 2 or 3) the trail follows
  CloudSettings cloud;             // an ensemble launched with the first run (scene/cloud.hpp)
  std::optional<SectionPanelSettings> section;  // a section panel beside the plane
  PageLayout page;                              // a screen picture, or a figure at a printed size

  int frame_count() const;  // round(fps * duration), at least 1
};

}  // namespace epviz::scene
