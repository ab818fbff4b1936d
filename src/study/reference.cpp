#include "study/reference.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace epviz::study {

double state_error(const sim::Sample& a, const sim::Sample& b) {
  return (a.omega - b.omega).norm() + (a.gamma - b.gamma).norm();
}

double fastest_period(const physics::InitialState& s) {
  const double w = s.omega.norm();
  return w > 0.0 ? 2.0 * std::numbers::pi / w : 1.0;
}

double reference_step(const physics::InitialState& initial) {
  return std::min(0.01, fastest_period(initial) / 200.0);
}

namespace {

// A run of (body, initial) in the direct formulation, method and accuracy to be set.
sim::RunSpec direct_run(const physics::Body& body, const physics::InitialState& initial,
                        double t_end, int samples) {
  sim::RunSpec spec;
  spec.body = body;
  spec.initial = initial;
  spec.formulation = sim::Formulation::direct;
  spec.t_end = t_end;
  spec.samples = samples;
  return spec;
}

// The largest step at most h_target that divides `spacing` (fixed steps must).
double dividing_step(double spacing, double h_target) {
  return spacing / std::ceil(spacing / h_target * (1.0 - 1e-12));
}

}  // namespace

Reference compute_reference(const physics::Body& body, const physics::InitialState& initial,
                            double t_end, int samples, double h_target) {
  const auto t0 = std::chrono::steady_clock::now();
  sim::RunSpec spec = direct_run(body, initial, t_end, samples);
  const double h = dividing_step(t_end / samples, h_target);

  spec.method = sim::Method::gauss6;
  spec.step = h;
  const auto coarse = sim::simulate(spec);
  spec.step = h / 2.0;
  const auto fine = sim::simulate(spec);
  spec.method = sim::Method::dop853;
  spec.tol = 1e-14;
  const auto check = sim::simulate(spec);
  for (const auto* r : {&coarse, &fine, &check})
    if (r->failure) throw std::runtime_error("reference run failed: " + r->failure->message());

  Reference ref;
  ref.step = h;
  ref.samples = fine.samples;
  for (std::size_t i = 0; i < ref.samples.size(); ++i) {
    auto& s = ref.samples[i];
    s.omega = (64.0 * fine.samples[i].omega - coarse.samples[i].omega) / 63.0;
    s.gamma = (64.0 * fine.samples[i].gamma - coarse.samples[i].gamma) / 63.0;
    ref.self_check = std::max(ref.self_check, state_error(s, check.samples[i]));
  }
  ref.cpu_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return ref;
}

double check_step(const physics::InitialState& initial) { return reference_step(initial) / 8.0; }

double CheckedReference::self_check() const {
  double worst = 0.0;
  for (double d : disagreement) worst = std::max(worst, d);
  return worst;
}

double CheckedReference::trusted_until(double margin) const {
  double t = samples.empty() ? 0.0 : samples.front().t;
  for (std::size_t i = 0; i < samples.size() && disagreement[i] <= margin; ++i) t = samples[i].t;
  return t;
}

CheckedReference compute_checked_reference(const physics::Body& body,
                                           const physics::InitialState& initial, double t_end,
                                           int samples, double h_target) {
  const auto t0 = std::chrono::steady_clock::now();
  sim::RunSpec spec = direct_run(body, initial, t_end, samples);
  CheckedReference ref;
  spec.method = sim::Method::dop853;
  spec.tol = ref.tol;
  const auto primary = sim::simulate(spec);
  spec.method = sim::Method::gauss6;
  spec.step = dividing_step(t_end / samples, h_target);
  const auto check = sim::simulate(spec);
  for (const auto* r : {&primary, &check})
    if (r->failure) throw std::runtime_error("reference run failed: " + r->failure->message());
  if (primary.samples.size() != check.samples.size())
    throw std::runtime_error("reference runs disagree on the output times");
  ref.check_step = spec.step;
  ref.samples = primary.samples;
  for (std::size_t i = 0; i < ref.samples.size(); ++i)
    ref.disagreement.push_back(state_error(ref.samples[i], check.samples[i]));
  ref.cpu_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return ref;
}

}  // namespace epviz::study
