#include "check/check_run.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <future>
#include <mutex>
#include <thread>

#include "check/html_report.hpp"
#include "check/job_check.hpp"
#include "check/junit_xml.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/output_paths.hpp"
#include "io/printable.hpp"

namespace epviz::check {

namespace fs = std::filesystem;

void check_output_paths(const std::string& report, const std::string& junit) {
  if (!report.empty()) {
    if (fs::exists(report) && !fs::is_directory(report))
      throw io::BadInput("--report: '" + io::printable(report, 200) +
                         "' exists and is not a directory");
    const auto parent = fs::absolute(report).parent_path();
    if (!fs::is_directory(parent))
      throw io::BadInput("--report: directory '" + io::printable(parent.string(), 200) +
                         "' does not exist");
  }
  io::check_output_file("--junit", junit);
}

namespace {

// The jobs handed out to the workers, one at a time, and their outcomes.
struct WorkQueue {
  explicit WorkQueue(std::size_t jobs) : outcomes(jobs) {}
  std::vector<std::promise<JobOutcome>> outcomes;
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::optional<RenderEnvironment> environment;  // the first worker's, for the report
};

// One worker: makes its source, then takes jobs until none is left. A worker
// without a source fails every job it takes with the reason.
void work(std::span<const GoldenJob> jobs, const RunSettings& s,
          const FrameSourceFactory& make_source, WorkQueue& queue) {
  std::unique_ptr<FrameSource> source;
  try {
    source = make_source();
  } catch (...) {
    const auto error = std::current_exception();
    for (std::size_t i; (i = queue.next.fetch_add(1)) < jobs.size();)
      queue.outcomes[i].set_exception(error);
    return;
  }
  {
    std::lock_guard lock(queue.mutex);
    if (!queue.environment) queue.environment = source->environment();
  }
  JobChecker checker(CheckSettings{s.tolerance, s.update ? fs::path() : s.report_dir,
                                   source->environment(), s.epviz_version, s.update_command});
  for (std::size_t i; (i = queue.next.fetch_add(1)) < jobs.size();) {
    try {
      // Each frame is checked as soon as it is drawn, and not kept.
      auto frames = checker.start(jobs[i], i, s.update);
      const auto failure =
          source->draw(i, jobs[i], [&](const ImageView& image) { frames.add(image); });
      queue.outcomes[i].set_value(frames.finish(failure));
    } catch (...) {
      queue.outcomes[i].set_exception(std::current_exception());
    }
  }
}

std::string environment_text(const RenderEnvironment& e) {
  return e.gl_renderer + ", OpenGL " + e.gl_version + "; font " + e.font_file;
}

int run(std::span<const GoldenJob> jobs, const RunSettings& s,
        const FrameSourceFactory& make_source, std::ostream& out, std::ostream& err) {
  const auto start = std::chrono::steady_clock::now();
  WorkQueue queue(jobs.size());
  std::vector<std::future<JobOutcome>> outcomes;
  for (auto& promise : queue.outcomes) outcomes.push_back(promise.get_future());
  std::vector<std::thread> threads;
  const int workers = std::max(1, std::min(s.workers, int(jobs.size())));
  for (int w = 0; w < workers; ++w)
    threads.emplace_back(work, jobs, std::cref(s), std::cref(make_source), std::ref(queue));

  // In job order, as each job's outcome arrives; after an error, only waiting.
  std::vector<FrameResult> results;
  int written = 0;
  std::exception_ptr error;
  for (auto& future : outcomes) {
    if (error) {
      future.wait();
      continue;
    }
    try {
      auto outcome = future.get();
      for (const auto& w : outcome.warnings) err << w << '\n';
      for (const auto& r : outcome.results) out << r.line() << '\n';
      for (const auto& l : outcome.lines) out << l << '\n';
      out.flush();
      written += outcome.goldens_written;
      for (auto& r : outcome.results) results.push_back(std::move(r));
    } catch (...) {
      error = std::current_exception();
    }
  }
  for (auto& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  out << (s.update ? update_summary(results, written) : summary(results)) << '\n';
  if (!s.update && !s.report_dir.empty()) {
    const auto index = s.report_dir / "index.html";
    io::write_file_atomically(
        index,
        html_report(results, {s.tolerance.describe(),
                              environment_text(queue.environment.value_or(RenderEnvironment{}))}));
    out << "report: " << index.string() << '\n';
  }
  if (!s.junit.empty())
    io::write_file_atomically(s.junit, junit_xml(results, seconds, s.update ? "" : s.report_dir));
  return all_passed(results) ? kExitPassed : kExitFrameFailed;
}

}  // namespace

int run_checks(std::span<const GoldenJob> jobs, const RunSettings& settings,
               const FrameSourceFactory& make_source, std::ostream& out, std::ostream& err) {
  try {
    return run(jobs, settings, make_source, out, err);
  } catch (const io::BadInput&) {
    throw;
  } catch (const fs::filesystem_error& e) {
    err << "epviz: error: '" << io::printable(e.path1().string(), 200)
        << "': " << e.code().message() << '\n';
  } catch (const std::exception& e) {
    err << "epviz: error: " << io::printable(e.what(), 400) << '\n';
  }
  return kExitCannotCheck;
}

}  // namespace epviz::check
