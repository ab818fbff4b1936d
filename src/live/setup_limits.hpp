#pragma once
// What a browser tab may set. Every number the panels hand over is checked
// before it reaches the scene: a job field against the field table's range
// (job/fields.hpp, the one `epviz render --help-job` prints), and the panel's
// own controls that no job has (speed, trail, nudge) against the bounds
// below. A typed value is not limited by a slider (ImGui lets Ctrl+click type
// any number, NaN and inf included), so this is where the limits hold.
#include <optional>
#include <string>

#include "live/live_setup.hpp"

namespace epviz::live {

// Simulation time per second of wall-clock time. A job has no speed (it
// spreads t_end over its duration); faster would only skip more of the motion
// between frames.
inline constexpr double kMinSpeed = 0.05, kMaxSpeed = 100.0;
// Simulation time the trail covers. A job's may be any positive number, but a
// render ends and a live run does not: the trail's points are kept in memory
// and drawn every frame, so a longer one would grow without end.
inline constexpr double kMinTrailLength = 0.5, kMaxTrailLength = 1000.0;
// The angle (radians) a compared run's gamma(0) is turned by: a nudge, not a new state.
inline constexpr double kMinNudge = 1e-12, kMaxNudge = 0.1;

// The first value that `edited` changed from `current` and that is out of its
// range, as one line for the panel: "tol 1e+300 is out of range (a number from
// 1e-15 to 0.1)"; nullopt when there is none. Values left as they were are
// not checked again: a served job may set a speed or trail the panel would
// not (its operator chose them), and an edit of something else keeps them.
std::optional<std::string> out_of_range(const LiveSetup& edited, const LiveSetup& current);

}  // namespace epviz::live
