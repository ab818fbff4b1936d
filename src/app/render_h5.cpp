#include "app/render_h5.hpp"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "app/h5_output.hpp"
#include "h5/columns_file.hpp"
#include "job/schema.hpp"
#include "scene/cloud_run.hpp"
#include "sim/failure_advice.hpp"
#include "sim/methods.hpp"
#include "sim/run_options.hpp"
#include "sweep/simulate_runs.hpp"
#include "sweep/simulation_output.hpp"

namespace epviz::app {
namespace {

// Run i of the plan: the first, then the others.
struct PlannedRunView {
  const sim::RunSpec& spec;
  const std::string& label;
  const std::string& accuracy;
};
PlannedRunView planned_run(const scene::ScenePlan& plan, std::size_t i) {
  if (i == 0) return {plan.run, plan.label, plan.accuracy_note};
  const auto& other = plan.others[i - 1];
  return {other.run, other.label, other.accuracy_note};
}

// One run into the group `group`, sample by sample. Returns its failure line, if any.
std::optional<std::string> write_run(h5::ColumnsFile& file, const std::string& group,
                                     const PlannedRunView& run,
                                     const io::ProgressOptions& progress) {
  const auto& names = sweep::sample_column_names();
  // A run's length is known: no chunk longer than the run.
  auto& table = file.add_table(
      group, std::vector<std::string>(names.begin(), names.end()),
      std::min<std::size_t>(h5::ColumnsFile::kChunkRows, std::size_t(run.spec.samples) + 1));
  const sweep::SampleColumns columns(run.spec);
  sim::RunDriftMonitor drifts(run.spec);
  io::ProgressOptions po = progress;
  po.label = "--h5 " + group;
  po.unit = "samples";
  io::ProgressLine line(run.spec.samples + 1, po);
  const auto result = sim::simulate(
      run.spec,
      [&](const sim::Sample& s) {
        drifts.output(s);
        table.append(columns.row(s).values);
        line.advance();
      },
      [&](const sim::Sample& s) { drifts.step(s); });
  line.finish();
  file.set_attribute(group + "/label", run.label);
  file.set_attribute(group + "/method", std::string(sim::name(run.spec.method)));
  file.set_attribute(group + "/formulation", std::string(sim::name(run.spec.formulation)));
  file.set_attribute(group + "/accuracy", run.accuracy);
  file.set_attribute(group + "/report",
                     sweep::simulate_report(run.spec, result, drifts.drifts()).dump());
  file.set_attribute(group + "/failed", long(result.failure ? 1 : 0));
  if (!result.failure) return std::nullopt;
  const std::string failure = sim::failure_line(*result.failure, sim::SettingsIn::render_job);
  file.set_attribute(group + "/failure", failure);
  return failure;
}

// The cloud into the group "cloud", a chunk of members at a time. Returns
// the number of members that failed.
long write_cloud(h5::ColumnsFile& file, const scene::ScenePlan& plan,
                 const scene::CloudSettings& cloud) {
  const auto& names = sweep::sample_column_names();  // t, omega1..3, gamma1..3, ...
  const std::vector<double> times = scene::cloud_times(plan);
  const auto members = std::size_t(cloud.members);
  file.write_column("cloud/t", times);
  for (std::size_t c = 0; c < 6; ++c)
    file.create_matrix("cloud/" + names[1 + c], members, times.size());
  std::vector<double> failure_t(members, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::string> failure_kind(members);
  long failed = 0;
  scene::integrate_cloud(
      plan.run, cloud, times, /*threads=*/2,
      [&](std::size_t first, const std::vector<sim::DirectBatchResult>& results) {
        const auto rows = scene::cloud_rows(first, results, times.size());
        for (std::size_t c = 0; c < 6; ++c)
          file.write_rows("cloud/" + names[1 + c], first, rows.state[c]);
        std::copy(rows.failure_t.begin(), rows.failure_t.end(), failure_t.begin() + long(first));
        std::copy(rows.failure_kind.begin(), rows.failure_kind.end(),
                  failure_kind.begin() + long(first));
        failed += rows.failed;
      });
  file.write_column("cloud/failure_t", failure_t);
  file.write_text_column("cloud/failure_kind", failure_kind);
  file.set_attribute("cloud/members", long(cloud.members));
  file.set_attribute("cloud/radius", cloud.radius);
  file.set_attribute("cloud/frames", long(plan.frames));
  file.set_attribute("cloud/run", std::string("run0"));
  file.set_attribute("cloud/method", std::string(sim::name(sim::Method::dop853)));
  file.set_attribute("cloud/formulation", std::string(sim::name(sim::Formulation::direct)));
  file.set_attribute("cloud/tol", sim::adaptive_tol(plan.run));
  file.set_attribute("cloud/failed_members", failed);
  return failed;
}

}  // namespace

RenderH5Written write_render_h5(const std::string& path, const job::RenderJob& job,
                                const scene::ScenePlan& plan, const nlohmann::json& report,
                                const io::ProgressOptions& progress) {
  h5::ColumnsFile file(path, {});
  RenderH5Written written;
  written.runs = 1 + int(plan.others.size());
  for (int i = 0; i < written.runs; ++i) {
    const auto failure =
        write_run(file, "run" + std::to_string(i), planned_run(plan, std::size_t(i)), progress);
    if (!failure) continue;
    ++written.failed_runs;
    if (!written.failure) written.failure = failure;
  }
  if (job.scene.cloud.enabled()) {
    written.cloud_members = job.scene.cloud.members;
    written.failed_members = write_cloud(file, plan, job.scene.cloud);
  }
  write_provenance(file);
  const job::JobDocument drawn{job.simulation, job.runs, job.scene, job.output};
  file.set_attribute("job", job::write_job(drawn).dump());
  file.set_attribute("report", report.dump());
  file.set_attribute("runs", long(written.runs));
  file.set_attribute("failed", long(written.failed_runs > 0 ? 1 : 0));
  if (written.failure) file.set_attribute("failure", *written.failure);
  file.commit();
  return written;
}

std::string render_h5_summary(const std::string& path, const RenderH5Written& written) {
  std::string line = path + ": " + std::to_string(written.runs) +
                     (written.runs == 1 ? " run" : " runs") + " (" +
                     std::to_string(written.failed_runs) + " failed)";
  if (written.cloud_members > 0)
    line += ", a cloud of " + std::to_string(written.cloud_members) + " members (" +
            std::to_string(written.failed_members) + " failed)";
  return line + "\n";
}

}  // namespace epviz::app
