#include "sweep/simulation_output.hpp"

#include <cstdio>
#include <limits>
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

// The header line: the column names, as the HDF5 datasets and Python's arrays are named.
std::string csv_header() {
  std::string header;
  for (const auto& name : sample_column_names()) header += (header.empty() ? "" : ",") + name;
  return header + "\n";
}

// Columns a (7), b (8) and extra_integral (12) may be absent: empty fields.
void append_row(std::string& out, const SampleColumns::Row& row) {
  for (std::size_t i = 0; i < kSampleColumns; ++i) {
    if (i > 0) out += ',';
    const bool absent = ((i == 7 || i == 8) && !row.has_ab) || (i == 12 && !row.has_extra);
    if (!absent) put(out, row.values[i]);
  }
  out += '\n';
}

constexpr std::size_t kChunk = 64 * 1024;

}  // namespace

const std::array<std::string, kSampleColumns>& sample_column_names() {
  static const std::array<std::string, kSampleColumns> names{
      "t", "omega1", "omega2", "omega3", "gamma1",           "gamma2",        "gamma3",
      "a", "b",      "energy", "area",   "gamma_norm_error", "extra_integral"};
  return names;
}

SampleColumns::SampleColumns(const sim::RunSpec& spec)
    : monitor_(spec.body, spec.case_id, spec.initial) {}

SampleColumns::Row SampleColumns::row(const sim::Sample& s) const {
  Row r;
  r.values.fill(std::numeric_limits<double>::quiet_NaN());
  r.values[0] = s.t;
  for (int i = 0; i < 3; ++i) {
    r.values[std::size_t(1 + i)] = s.omega[i];
    r.values[std::size_t(4 + i)] = s.gamma[i];
  }
  if (auto ab = physics::stereographic(s.gamma)) {
    r.has_ab = true;
    r.values[7] = (*ab)[0];
    r.values[8] = (*ab)[1];
  }
  const auto inv = monitor_.at(s);
  r.values[9] = inv.energy;
  r.values[10] = inv.area;
  r.values[11] = s.gamma.norm() - 1.0;
  if (inv.extra) {
    r.has_extra = true;
    r.values[12] = *inv.extra;
  }
  return r;
}

SamplesCsvWriter::SamplesCsvWriter(const sim::RunSpec& spec, io::AtomicFile& file)
    : columns_(spec), file_(file), buffer_(csv_header()) {
  buffer_.reserve(kChunk + 1024);
}

void SamplesCsvWriter::add(const sim::Sample& s) {
  append_row(buffer_, columns_.row(s));
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
