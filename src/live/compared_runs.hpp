#pragma once
// The runs the interactive scene compares with its own (the first): each is
// the first run with one thing changed, so that an edit of the body or the
// state applies to every run and the saved job says only what differs.
#include <optional>
#include <string>
#include <vector>

#include "scene/plan.hpp"
#include "sim/run_spec.hpp"

namespace epviz::live {

struct LiveSetup;

struct ComparedRun {
  // Another method with its own step or tolerance (the one its kind uses).
  std::optional<sim::Method> method;
  double step = 0.1;
  double tol = 1e-8;
  // The first run's gamma(0) turned by this angle (radians), so that the
  // runs start |delta gamma| = 2 sin(nudge / 2) apart; 0: not nudged.
  double nudge = 0.0;
  // A run as a served job's "runs" gave it: drawn as given (the fields above
  // unused), and edits of the first run leave it as it is.
  std::optional<scene::RunRequest> given;
};

// The first run with another method (and the step or tolerance of its kind).
ComparedRun with_method(sim::Method method, double step, double tol);
// The first run with gamma(0) turned by `angle` radians.
ComparedRun nudged_by(double angle);

// gamma turned by `angle` about an axis perpendicular to it (a unit vector stays one).
Eigen::Vector3d nudged_gamma(const Eigen::Vector3d& gamma, double angle);

// The run `c` describes, from the first run. A nudged state that breaks the
// case's conditions runs as a custom body, as an edited one does.
sim::RunSpec compared_spec(const sim::RunSpec& first, const ComparedRun& c);

// The legend's label of a compared run: "nudged 1e-06" for a nudged state,
// empty for another method (the legend names the method and its accuracy),
// the job's for a given run.
std::string compared_label(const ComparedRun& c);

// Every run of the setup for the scene's plan, the first first.
std::vector<scene::RunRequest> run_requests(const LiveSetup& setup);

}  // namespace epviz::live
