#pragma once
// A cloud: an ensemble of nearby initial states launched with a render job's
// run, drawn as points on the sphere and in the (a, b) plane, and the one
// number that says how far it has spread. Plain values only: scene/cloud_run.hpp
// integrates it, the painter (src/paint/cloud_drawing.hpp) draws it.
#include <Eigen/Core>
#include <vector>

namespace epviz::scene {

inline constexpr int kMinCloudMembers = 1, kMaxCloudMembers = 100'000;
inline constexpr int kDefaultCloudMembers = 10'000;
inline constexpr double kDefaultCloudRadius = 0.05;  // radians of gamma on the sphere
inline constexpr double kMaxCloudRadius = 1.0;

// What a job asks for: `members` states whose gamma fills a disc (a spherical
// cap) of angular `radius` about the run's gamma. members == 0: no cloud.
struct CloudSettings {
  int members = 0;
  double radius = kDefaultCloudRadius;
  bool enabled() const { return members > 0; }
};

// One frame of the cloud.
struct CloudFrame {
  std::vector<Eigen::Vector3f> sphere;  // gamma of each member still running (body frame)
  std::vector<Eigen::Vector2f> plane;   // their (a, b), only those inside the panel
  // The spread (cloud_spread in scene/cloud_run.hpp) at each frame so far: (t, fraction).
  std::vector<Eigen::Vector2f> spread;
  int members = 0;     // launched (those that failed are no longer drawn)
  double t_end = 0.0;  // the last frame's time (the spread chart's axis)
  // > 0: the spread chart's time axis ends here instead, so that a gallery's
  // tiles of runs of different lengths share one scale (paint::FrameDrawer).
  double chart_t_end = 0.0;
};

}  // namespace epviz::scene
