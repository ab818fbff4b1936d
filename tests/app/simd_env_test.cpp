// EPVIZ_SIMD names the batch integrator's instruction set; a value that names
// none is bad input for every command, refused before any work: a sharded
// sweep or section starts no shard.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli.hpp"
#include "support/simd_env.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

TEST(SimdEnvironment, AValueNamingNoPathIsRefusedBeforeAnyWork) {
  test::TempDir dir;
  const std::string sweep =
      (fs::path(EPVIZ_SOURCE_DIR) / "render_jobs/ftle_curves.sweep.json").string();
  const std::string section =
      (fs::path(EPVIZ_SOURCE_DIR) / "render_jobs/generic.section.json").string();
  test::ScopedSimdEnv env("avx9");
  for (const std::string& args :
       {"sweep " + sweep + " --out " + (dir / "rows.jsonl").string() + " --shard 0/2",
        "section " + section + " --out " + (dir / "crossings.csv").string() + " --shard 0/2",
        std::string("cases")}) {
    const auto r = test::run_epviz(args, dir);
    test::expect_bad_input(r, "EPVIZ_SIMD='avx9'");
    EXPECT_NE(r.err.find("avx512"), std::string::npos) << "the allowed values: " << r.err;
  }
  EXPECT_EQ(dir.file_count(), 0u) << "a shard was started";
}

}  // namespace
}  // namespace epviz
