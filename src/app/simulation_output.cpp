#include "app/simulation_output.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/failure_advice.hpp"
#include "physics/stereographic.hpp"

namespace epviz::app {
namespace {

void put(std::string& out, double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  out += buf;
}

nlohmann::json number_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

constexpr const char* kCsvHeader =
    "t,omega1,omega2,omega3,gamma1,gamma2,gamma3,a,b,energy,area,gamma_norm_error,"
    "extra_integral\n";

void append_row(std::string& out, const sim::InvariantMonitor& monitor, const sim::Sample& s) {
  put(out, s.t);
  for (int i = 0; i < 3; ++i) {
    out += ',';
    put(out, s.omega[i]);
  }
  for (int i = 0; i < 3; ++i) {
    out += ',';
    put(out, s.gamma[i]);
  }
  if (auto ab = physics::stereographic(s.gamma)) {
    out += ',';
    put(out, (*ab)[0]);
    out += ',';
    put(out, (*ab)[1]);
  } else {
    out += ",,";
  }
  const auto inv = monitor.at(s);
  out += ',';
  put(out, inv.energy);
  out += ',';
  put(out, inv.area);
  out += ',';
  put(out, s.gamma.norm() - 1.0);
  out += ',';
  if (inv.extra) put(out, *inv.extra);
  out += '\n';
}

constexpr std::size_t kChunk = 64 * 1024;

}  // namespace

std::string samples_csv(const sim::RunSpec& spec, const sim::RunResult& result) {
  std::string out = kCsvHeader;
  out.reserve(out.size() + result.samples.size() * 13 * 24);
  sim::InvariantMonitor monitor(spec.body, spec.case_id, spec.initial);
  for (const auto& s : result.samples) append_row(out, monitor, s);
  return out;
}

SamplesCsvWriter::SamplesCsvWriter(const sim::RunSpec& spec, io::AtomicFile& file)
    : monitor_(spec.body, spec.case_id, spec.initial), file_(file), buffer_(kCsvHeader) {
  buffer_.reserve(kChunk + 1024);
}

void SamplesCsvWriter::add(const sim::Sample& s) {
  append_row(buffer_, monitor_, s);
  if (buffer_.size() >= kChunk) flush();
}

void SamplesCsvWriter::flush() {
  file_.write(buffer_);
  buffer_.clear();
}

nlohmann::json run_report(const sim::RunSpec& spec, const sim::RunResult& r,
                          const sim::Drifts& drift) {
  nlohmann::json j;
  j["case"] = physics::case_name(spec.case_id);
  j["formulation"] = std::string(sim::name(spec.formulation));
  j["method"] = std::string(sim::name(spec.method));
  if (sim::is_adaptive(spec.method)) {
    j["tol"] = spec.tol;
  } else {
    j["step"] = spec.step;
    j["effective_step"] = r.effective_step;
  }
  if (spec.formulation == sim::Formulation::riccati) {
    j["chart_switch"] = spec.chart_switch;
    j["chart_switches"] = r.chart_switches;
  }
  j["body"] = {{"inertia", {spec.body.inertia[0], spec.body.inertia[1], spec.body.inertia[2]}},
               {"com", {spec.body.com[0], spec.body.com[1], spec.body.com[2]}},
               {"weight", spec.body.weight}};
  j["initial"] = {{"omega", {spec.initial.omega[0], spec.initial.omega[1], spec.initial.omega[2]}},
                  {"gamma", {spec.initial.gamma[0], spec.initial.gamma[1], spec.initial.gamma[2]}}};
  j["t_end"] = spec.t_end;
  j["samples"] = spec.samples;
  j["samples_written"] = r.samples_written;
  j["steps"] = r.stats.steps;
  j["rhs_evals"] = r.stats.rhs_evals;
  j["rejected_steps"] = r.stats.rejected_steps;
  j["solver_iterations"] = r.stats.solver_iterations;
  j["cpu_seconds"] = r.cpu_seconds;
  nlohmann::json d = {{"gamma_norm2", number_or_null(drift.gamma_norm2)},
                      {"area", number_or_null(drift.area)},
                      {"energy", number_or_null(drift.energy)}};
  d["extra_integral"] = drift.extra ? number_or_null(*drift.extra) : nlohmann::json(nullptr);
  j["max_relative_drift"] = d;
  if (r.failure) {
    const bool adaptive = sim::is_adaptive(spec.method);
    j["failure"] = {{"t", r.failure->t},
                    {"method", r.failure->method},
                    {"detail", r.failure->detail},
                    {"advice", failure_advice(r.failure->kind, r.failure->method, adaptive)},
                    {"message", failure_line(*r.failure)}};
    j["failure_kind"] = std::string(numerics::name(r.failure->kind));
  } else {
    j["failure"] = nullptr;
    j["failure_kind"] = nullptr;
  }
  return j;
}

}  // namespace epviz::app
