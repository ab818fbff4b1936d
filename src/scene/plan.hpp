#pragma once
// From a job to what must be simulated: the formulation the view needs, the
// tolerance the resolution needs, and the output times of frames and trails.
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/layout.hpp"
#include "scene/settings.hpp"
#include "sim/run_spec.hpp"

namespace epviz::scene {

class PlanError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A run of a comparison scene beyond the first: same frame times, its own
// method, accuracy, formulation, body or initial state.
struct PlannedRun {
  sim::RunSpec run;
  std::string label;          // the legend's name ("" when the job gave none)
  std::string accuracy_note;  // as ScenePlan::accuracy_note
};

// What a job asks of one run before the plan resolves it.
struct RunRequest {
  sim::RunSpec run;
  std::string label;
  bool formulation_given = false;  // else the view picks it
  bool auto_tolerance = true;      // adaptive methods: tolerance from the resolution
};

struct ScenePlan {
  sim::RunSpec run;  // samples = (frames - 1) * substeps_per_frame (at least 1 frame interval)
  int frames = 1;
  int samples_per_frame = 8;  // trail samples between two frames
  std::string accuracy_note;  // how the tolerance or step was chosen, for the report and overlay
  bool open_ended =
      false;  // interactive: no last frame; run.t_end only sets the sample spacing's horizon
  FrameLayout layout;  // the picture the frames are drawn into (the tolerance follows it)
  // Pixels per unit of gamma on the sphere and of (a, b) on the plane that the
  // trails are decimated for (see trail_pixel_scales).
  double trail_sphere_px = 0.0, trail_plane_px = 0.0;
  double frame_time(int frame) const;  // simulation time shown by a frame

  // Comparison scenes (a job's "runs"): the first run is `run`, named `label`;
  // the others follow, integrated to the same sample times.
  std::string label;
  std::vector<PlannedRun> others;
  bool comparison() const { return !others.empty(); }
  // Each run is shadowed by a more accurate one (tolerance / 100, or half the
  // step) to find where its picture stops being true to half a pixel.
  bool shadow = true;
};

// The relative error of a shadow run, against that of the run it shadows
// (fixed step: half the step; adaptive: a hundredth of the tolerance).
sim::RunSpec shadow_run(const sim::RunSpec& run);
// How much larger the run's own error is than its distance from the shadow
// (Richardson: 2^p / (2^p - 1) for a fixed step of order p).
double shadow_error_factor(const sim::RunSpec& run);

// The layout of the frames of this job: the painter's own (scene::frame_layout),
// with the overlay FrameSource composes for this run.
FrameLayout planned_layout(const SceneSettings& s, const sim::RunSpec& run);
// The same for a comparison scene of these runs (the overlay's drift rows per
// run, the separation chart under the plane).
FrameLayout planned_layout(const SceneSettings& s, const std::vector<sim::RunSpec>& runs);
// A figure at a printed size: `width` pixels wide, its text `font_px` tall,
// its parts stacked (PageLayout) and as tall as they need.
void set_printed_size(SceneSettings& s, const std::vector<sim::RunSpec>& runs, int width,
                      float font_px);

// The largest scale the sphere and the plane take in a picture of this size:
// each alone in it. Trails are decimated for these, so that a layer switched
// on interactively (which keeps the run, and its plan) never shows a coarse trail.
void trail_pixel_scales(const SceneSettings& s, double& sphere_px, double& plane_px);

// The relative/absolute tolerance that keeps the drawn error well below a pixel
// over the run: tol = 0.02 px / (pixels per unit of gamma, with the plane's
// magnification at its edge) / (1 + t_end / 10) for the growth of the global
// error, clamped to [1e-13, 1e-4]. The factor 0.02 is calibrated so that the
// measured error of every integrable preset stays under 0.1 px
// (tests/scene/plan_test.cpp checks < 0.5 px against tol 1e-13).
double tolerance_for_layout(const FrameLayout& layout, float plane_extent, double t_end);
// The largest pixels per unit of gamma anywhere in the picture (the plane's at its edge).
double pixels_per_gamma(const FrameLayout& layout, float plane_extent);

// Whether "auto" tolerances look ahead for the picture's horizon: a render
// does (its runs end), an interactive scene does not (its run has no end).
enum class Horizon { search, none };

// The tightest tolerance "auto" goes to when chaos shortens the horizon: the
// shadow, a hundred times tighter, is then still above round-off.
inline constexpr double kTightestAutoTolerance = 1e-12;

// Throws PlanError when the job asks for something the view cannot show (the
// space view needs the attitude, i.e. the spinor formulation).
// With Horizon::search, an "auto" tolerance is the resolution's
// (tolerance_for_layout) when its picture stays true to half a pixel to the
// end (the shadow run says); else (chaotic runs, long runs) the tolerance a
// hundredfold tighter at a time down to kTightestAutoTolerance whose picture
// stays true longest: as long as the numbers allow, and the report and
// overlay give the honest horizon after that.
ScenePlan plan_scene(sim::RunSpec run, const SceneSettings& s, Horizon h = Horizon::search);
// A comparison scene: every run resolved as above (the first decides the
// layout together with the others' count), all to the same frame times.
ScenePlan plan_scene(std::vector<RunRequest> runs, const SceneSettings& s,
                     Horizon h = Horizon::search);

}  // namespace epviz::scene
