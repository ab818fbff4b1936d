// epviz_bench's main: Google Benchmark's console output, then, when the
// ensemble benchmarks ran, their ceiling and the share of it the batch
// reaches on each instruction set (docs/ensembles.md):
//   ceiling = scalar stepper's ns a step / attempt-only ns a step (its W lanes)
//   reached = scalar stepper's ns a step / batch's ns a step (same W)
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

// Keeps each ensemble benchmark's "per_step" (the median when repeated).
class EnsembleReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      const std::string name = r.run_name.str();
      if (name.rfind("ensemble_", 0) != 0) continue;
      const auto c = r.counters.find("per_step");
      if (c == r.counters.end()) continue;
      const bool median = r.run_type == Run::RT_Aggregate && r.aggregate_name == "median";
      if (r.run_type == Run::RT_Iteration && !medians_.count(name)) per_step_[name] = c->second;
      if (median) {
        per_step_[name] = c->second;
        medians_[name] = true;
      }
    }
  }

  void print_ceilings() const {
    const auto scalar = per_step_.find("ensemble_scalar_dop853");
    if (scalar == per_step_.end()) return;
    bool header = false;
    for (const auto& [name, attempt] : per_step_) {
      const std::string prefix = "ensemble_attempt_only/";
      if (name.rfind(prefix, 0) != 0) continue;
      const std::string isa_w = name.substr(prefix.size());  // "avx512/W8"
      const auto batch = per_step_.find("ensemble_batch_dop853/" + isa_w);
      if (batch == per_step_.end() || !(attempt > 0.0) || !(batch->second > 0.0)) continue;
      if (!header) {
        std::printf("\nensemble speed-up over the scalar stepper (%.1f ns a step):\n",
                    1e9 * scalar->second);
        header = true;
      }
      const double ceiling = scalar->second / attempt;
      const double reached = scalar->second / batch->second;
      std::printf("  %-12s ceiling %.2fx (attempt only), batch %.2fx: %.0f %% of the ceiling\n",
                  isa_w.c_str(), ceiling, reached, 100.0 * reached / ceiling);
    }
  }

 private:
  std::map<std::string, double> per_step_;
  std::map<std::string, bool> medians_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  EnsembleReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ceilings();
  benchmark::Shutdown();
  return 0;
}
