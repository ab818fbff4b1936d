#pragma once
// `epviz bench`: work-precision, long-time invariant drift and stability
// studies of epviz's own methods; tables on stdout, every row to JSON.
#include <functional>
#include <string>

#include "app/cli.hpp"
#include "io/print_size.hpp"

namespace epviz::app {

// Adds the subcommand to `app`; the returned function runs it after parsing and
// returns the process exit code.
std::function<int()> add_bench_command(cli::Command app);

// What a bench run is asked for, from the command line or a render job
// (render_jobs/bench_figures.json: `epviz render` draws the bench's figures).
struct BenchRequest {
  bool quick = false;
  std::string json;          // write the rows here ("" for none)
  std::string out;           // directory for bench.json and the charts ("" for none)
  std::string cases;         // comma-separated presets ("" for all)
  std::string gl;            // GL backend for the charts ("" for $EPVIZ_GL or auto)
  std::string format;        // the charts' files: png, svg or pdf ("" for png)
  std::string job;           // a render or simulate job whose body to study too ("" for none)
  std::string target_error;  // with a job: the error the recommendation must reach ("" for 1e-8)
  io::PrintSizeText print;   // the charts' printed size ("" each where not given)
};
int run_bench(const BenchRequest& request);

}  // namespace epviz::app
