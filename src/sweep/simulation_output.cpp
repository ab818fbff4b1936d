#include "sweep/simulation_output.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "io/json_line.hpp"
#include "io/json_text.hpp"
#include "physics/stereographic.hpp"
#include "sim/failure_advice.hpp"
#include "sweep/run_record.hpp"

namespace epviz::sweep {
namespace {

void put(std::string& out, double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  out += buf;
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
  // The members a sweep's row has too, then the report's own.
  io::JsonLine shared;
  shared.begin_object();
  write_run_record(shared, spec, r, drift);
  shared.end_object();
  nlohmann::json j = io::parse_json(shared.str());
  if (spec.formulation == sim::Formulation::riccati) {
    j["chart_switch"] = spec.chart_switch;
    j["chart_switches"] = r.chart_switches;
  }
  j["body"] = {{"inertia", {spec.body.inertia[0], spec.body.inertia[1], spec.body.inertia[2]}},
               {"com", {spec.body.com[0], spec.body.com[1], spec.body.com[2]}},
               {"weight", spec.body.weight}};
  j["samples"] = spec.samples;
  j["solver_iterations"] = r.stats.solver_iterations;
  j["failure"] = nullptr;
  if (r.failure) {
    const bool adaptive = sim::is_adaptive(spec.method);
    j["failure"] = {{"t", r.failure->t},
                    {"method", r.failure->method},
                    {"detail", r.failure->detail},
                    {"advice", sim::failure_advice(r.failure->kind, r.failure->method, adaptive,
                                                   sim::SettingsIn::command_line)},
                    {"message", sim::failure_line(*r.failure, sim::SettingsIn::command_line)}};
  }
  return j;
}

}  // namespace epviz::sweep
