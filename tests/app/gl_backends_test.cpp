// The gallery's jobs drawn through EGL and through OSMesa give the same
// pictures: goldens written by `epviz check --update` on one backend pass
// `epviz check` on the other with no tolerance at all (threshold 0, no pixel
// allowed to differ), and the other way round.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;

std::string gallery() { return std::string(EPVIZ_SOURCE_DIR) + "/render_jobs/gallery.json"; }

// The first, middle and last frame of every gallery job, at the job's size.
std::string check_args(const test::TempDir& dir, const std::string& backend) {
  return "check " + gallery() + " --golden " + (dir / "golden").string() + " --gl " + backend +
         " --threshold 0 --max-differing 0";
}

TEST(GlBackends, GalleryGoldensFromEachBackendPassOnTheOther) {
  for (const auto& [writer, checker] : {std::pair{"egl", "osmesa"}, std::pair{"osmesa", "egl"}}) {
    test::TempDir dir;
    const auto update = test::run_epviz(check_args(dir, writer) + " --update", dir);
    ASSERT_EQ(update.exit_code, 0) << writer << ": " << update.err;
    ASSERT_TRUE(fs::exists(dir / "golden")) << writer;
    const auto check = test::run_epviz(check_args(dir, checker), dir);
    EXPECT_EQ(check.exit_code, 0) << writer << " goldens on " << checker << ":\n"
                                  << check.out << check.err;
    EXPECT_NE(check.out.find(" passed, 0 failed"), std::string::npos) << check.out;
  }
}

}  // namespace
}  // namespace epviz
