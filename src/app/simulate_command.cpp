#include "app/simulate_command.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/cli_values.hpp"
#include "app/h5_output.hpp"
#include "app/simulation_fields.hpp"
#include "h5/columns_file.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/json_text.hpp"
#include "io/output_paths.hpp"
#include "io/progress.hpp"
#include "io/temp_name.hpp"
#include "io/temp_registry.hpp"
#include "physics/cases.hpp"
#include "sim/failure_advice.hpp"
#include "sweep/simulate_runs.hpp"
#include "sweep/simulation_output.hpp"

namespace epviz::app {
namespace {

struct RawOptions {
  std::string job, csv, report_json, h5, max_steps;
  SimulationOptions sim;
};

SimulationFields fields_from_job(const std::string& path) {
  auto json = io::read_json_file(path);
  io::ObjectReader reader(json, path);
  auto f = read_simulation_fields(reader);
  reader.finish();
  return f;
}

int run_simulate(const RawOptions& raw) {
  SimulationFields fields;
  if (!raw.job.empty()) fields = fields_from_job(raw.job);
  fields.overlay(fields_from_options(raw.sim));
  require_separate_files(
      {{"--job", raw.job}},
      {{"--csv", raw.csv}, {"--report-json", raw.report_json}, {"--h5", raw.h5}});
  io::check_output_file("--csv", raw.csv);
  io::check_output_file("--report-json", raw.report_json);
  h5::check_h5_output("--h5", raw.h5);
  const bool csv_to_stdout = !raw.csv.empty() && io::writes_to_standard_output(raw.csv);
  const bool report_to_stdout =
      !raw.report_json.empty() && io::writes_to_standard_output(raw.report_json);
  if (csv_to_stdout && report_to_stdout)
    throw io::BadInput(
        "--report-json: standard output already carries the samples (--csv); write one of them "
        "to a file");

  if (sweep::runs_every_case(fields) && !raw.csv.empty())
    throw io::BadInput("--csv: writes one run's samples; it cannot be combined with --case all");
  if (sweep::runs_every_case(fields) && !raw.h5.empty())
    throw io::BadInput("--h5: writes one run's samples; it cannot be combined with --case all");
  std::optional<long> max_steps;
  if (!raw.max_steps.empty())
    max_steps = long(parse_integer("--max-steps", raw.max_steps, 1, 1'000'000'000'000));
  // Every run is resolved before any is integrated: bad input leaves nothing behind.
  const std::vector<sim::RunSpec> specs = sweep::simulate_runs(fields, max_steps);

  // When standard output carries data, the summary goes to stderr so that it
  // cannot corrupt the data.
  std::FILE* summary = csv_to_stdout || report_to_stdout ? stderr : stdout;
  io::install_temporary_cleanup();
  io::remove_stale_temporaries_beside(raw.csv);
  io::remove_stale_temporaries_beside(raw.report_json);
  io::remove_stale_temporaries_beside(raw.h5);

  nlohmann::json reports = nlohmann::json::array();
  int failures = 0;
  // The samples are written as they are produced: memory stays flat however
  // many --samples are asked for.
  std::optional<io::AtomicFile> csv_file;
  if (!raw.csv.empty()) csv_file.emplace(raw.csv);
  // The HDF5 file's datasets grow a chunk at a time (h5/columns_file.hpp).
  std::optional<h5::ColumnsFile> h5_file;
  if (!raw.h5.empty()) {
    const auto& names = sweep::sample_column_names();
    h5_file.emplace(raw.h5, std::vector<std::string>(names.begin(), names.end()));
  }
  for (const auto& spec : specs) {
    sim::RunDriftMonitor drifts(spec);
    std::optional<sweep::SamplesCsvWriter> csv;
    if (csv_file) csv.emplace(spec, *csv_file);
    std::optional<sweep::SampleColumns> columns;
    if (h5_file) columns.emplace(spec);
    io::ProgressOptions po;
    po.label = "simulate " + physics::case_name(spec.case_id);
    po.unit = "samples";
    io::ProgressLine progress(spec.samples + 1, po);
    const auto result = sim::simulate(
        spec,
        [&](const sim::Sample& s) {
          drifts.output(s);
          if (csv) csv->add(s);
          if (h5_file) h5_file->append(columns->row(s).values);
          progress.advance();
        },
        [&](const sim::Sample& s) { drifts.step(s); });
    progress.finish();
    if (csv) csv->flush();
    std::fputs(sweep::run_summary(spec, result, drifts.drifts()).c_str(), summary);
    reports.push_back(sweep::simulate_report(spec, result, drifts.drifts()));
    if (h5_file) {
      // A failed run keeps the samples before its failure, marked failed.
      write_provenance(*h5_file);
      h5_file->set_attribute("job", given_fields_json(fields).dump());
      h5_file->set_attribute("report", reports.back().dump());
      h5_file->set_attribute("failed", long(result.failure ? 1 : 0));
      if (result.failure)
        h5_file->set_attribute("failure",
                               sim::failure_line(*result.failure, sim::SettingsIn::command_line));
    }
    if (result.failure) {
      ++failures;
      std::fprintf(stderr, "epviz: %s\n",
                   sim::failure_line(*result.failure, sim::SettingsIn::command_line).c_str());
    }
  }
  std::fflush(summary);
  if (csv_file) csv_file->commit();
  if (h5_file) h5_file->commit();
  if (!raw.report_json.empty())
    io::write_file_atomically(raw.report_json,
                              io::json_text(specs.size() == 1 ? reports[0] : reports, 2) + "\n");
  return failures ? 3 : 0;
}

}  // namespace

std::function<int()> add_simulate_command(cli::Command app) {
  auto raw = std::make_shared<RawOptions>();
  cli::Command cmd =
      app.add_subcommand("simulate", "Integrate one body (or every preset) and write samples");
  cmd.add_option("--job", raw->job,
                 "JSON job file with the same fields (options given here override it)");
  add_simulation_options(cmd, raw->sim);
  cmd.add_option("--max-steps", raw->max_steps,
                 "adaptive methods: end the run as failed after this many steps (default 1e8)");
  cmd.add_option("--csv", raw->csv,
                 "write the samples to this CSV file ('-': standard output; the summary then "
                 "goes to stderr)");
  cmd.add_option("--report-json", raw->report_json,
                 "write the run report to this JSON file ('-': standard output)");
  cmd.add_option("--h5", raw->h5,
                 "write the samples to this HDF5 file: a float64 dataset per CSV column, the "
                 "job and the report as attributes (JSON)");
  return [raw] { return run_simulate(*raw); };
}

}  // namespace epviz::app
