#pragma once
// Parameters of the heavy rigid body and its initial state, with validation.
#include <Eigen/Core>
#include <stdexcept>
#include <string>

namespace epviz::physics {

using Eigen::Vector3d;

// Principal moments (I1, I2, I3), centre of mass (a0, b0, c0) in the body's
// principal axes, weight P = m g.
struct Body {
  Vector3d inertia{1.0, 2.0, 3.0};
  Vector3d com{0.0, 0.0, 0.0};
  double weight = 1.0;
};

// Body angular velocity Omega and the unit vertical gamma, both in body axes.
struct InitialState {
  Vector3d omega{0.0, 0.0, 0.0};
  Vector3d gamma{0.0, 0.0, 1.0};
};

// A check the user may waive on purpose; the front ends say how (an option, a
// job key), physics only says which.
enum class Waiver {
  none,
  allow_nonphysical,  // moments that break the triangle inequalities
  normalize_gamma,    // a gamma that is not a unit vector, rescaled
};

// Bad user input. `field` names what the user wrote ("inertia", "gamma", ...)
// so the CLI and the job loader can name the option or key.
class InvalidInput : public std::runtime_error {
 public:
  InvalidInput(std::string field, const std::string& what, Waiver waiver = Waiver::none)
      : std::runtime_error(what), field_(std::move(field)), waiver_(waiver) {}
  const std::string& field() const noexcept { return field_; }
  Waiver waiver() const noexcept { return waiver_; }

 private:
  std::string field_;
  Waiver waiver_;
};

// Throws InvalidInput unless every number is finite, the moments are positive
// and (unless allow_nonphysical) satisfy the triangle inequalities, and the
// weight is non-negative.
void validate_body(const Body& body, bool allow_nonphysical);

// Returns gamma if | |gamma| - 1 | <= 1e-9, gamma / |gamma| if normalize is set
// (and |gamma| > 0), otherwise throws InvalidInput("gamma", ...). Also rejects
// non-finite omega/gamma components (field "omega" / "gamma").
InitialState validate_initial_state(const InitialState& s, bool normalize);

}  // namespace epviz::physics
