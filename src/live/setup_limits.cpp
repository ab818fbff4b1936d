#include "live/setup_limits.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "job/fields.hpp"

namespace epviz::live {
namespace {

// A bound of the panel's own, worded as the field table words its ranges.
job::FieldInfo panel_number(const char* name, double lo, double hi) {
  job::FieldInfo f;
  f.key = name;
  f.type = job::FieldType::number;
  f.min = lo;
  f.max = hi;
  return f;
}

const job::FieldInfo& table_field(const char* key) {
  const job::FieldInfo* f = job::find_field(key);
  // Every key named here is in the table; a renamed one is a bug caught by the tests.
  if (!f) throw std::logic_error(std::string("no simulation field '") + key + "'");
  return *f;
}

std::string shown(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// Collects the first problem; the checks after it are skipped.
class Checker {
 public:
  // Infinity is no number a job can hold (JSON has none), though "a
  // positive number" has no upper bound.
  void number(const job::FieldInfo& f, double v) {
    if (!problem_ && !(std::isfinite(v) && f.in_range(v)))
      problem_ = f.key + " " + shown(v) + " is out of range (" + f.range_text() + ")";
  }
  void vec3(const job::FieldInfo& f, const Eigen::Vector3d& v) {
    for (int i = 0; i < 3; ++i) number(f, v[i]);
  }
  std::optional<std::string> problem() const { return problem_; }

 private:
  std::optional<std::string> problem_;
};

// Whether a value differs from the one running (a NaN always does).
bool changed(double a, double b) { return !(a == b); }
bool changed(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return changed(a.x(), b.x()) || changed(a.y(), b.y()) || changed(a.z(), b.z());
}

}  // namespace

std::optional<std::string> out_of_range(const LiveSetup& edited, const LiveSetup& current) {
  Checker check;
  const sim::RunSpec &e = edited.run, &c = current.run;
  if (changed(e.body.inertia, c.body.inertia)) check.vec3(table_field("inertia"), e.body.inertia);
  if (changed(e.body.com, c.body.com)) check.vec3(table_field("com"), e.body.com);
  if (changed(e.body.weight, c.body.weight)) check.number(table_field("weight"), e.body.weight);
  if (changed(e.initial.omega, c.initial.omega)) check.vec3(table_field("omega"), e.initial.omega);
  if (changed(e.initial.gamma, c.initial.gamma)) check.vec3(table_field("gamma"), e.initial.gamma);
  if (changed(e.tol, c.tol)) check.number(table_field("tol"), e.tol);
  if (changed(e.step, c.step)) check.number(table_field("step"), e.step);
  if (changed(edited.speed, current.speed))
    check.number(panel_number("speed", kMinSpeed, kMaxSpeed), edited.speed);
  if (changed(edited.scene.trail_length, current.scene.trail_length))
    check.number(panel_number("trail length", kMinTrailLength, kMaxTrailLength),
                 edited.scene.trail_length);
  // The runs the panel added (each the first run with one thing changed); a
  // served job's own were read by the job reader.
  for (const ComparedRun& run : edited.compared) {
    if (run.given) continue;
    if (run.method)
      check.number(table_field(sim::is_adaptive(*run.method) ? "tol" : "step"),
                   sim::is_adaptive(*run.method) ? run.tol : run.step);
    if (run.nudge != 0.0) check.number(panel_number("nudge", kMinNudge, kMaxNudge), run.nudge);
  }
  return check.problem();
}

}  // namespace epviz::live
